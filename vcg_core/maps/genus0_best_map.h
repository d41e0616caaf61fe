// The genus-0 map as `parameterize` makes it, from the solves of genus0_map.h.
//
// In:  a closed genus-0 mesh (unit scale), its edges and cotangent weights, the solver, the pole
//      face asked for (-1: automatic) and the surface area per vertex (the centring's weights).
// Out: the values in the extended plane, the pole face used and how many weights were raised.
//      The plain cotangent map is tried first; where it folds, weights are raised to positive
//      ones near the folds (two rings), round by round (solved again within ten rings of them,
//      or on the whole mesh by updating the factor for the few changed weights, or by a new
//      factorization), all of them at the end. Its shear is removed and its pole region solved
//      again (genus0_correction.h). With CHOLMOD, the first factorization eliminates the south
//      cap predicted from a coarse map last, so that one factorization serves the map and the
//      south-pole step (south_cap_prediction.h). With an automatic pole,
//      where the centred map folds or crowds faces below double precision, the map is solved
//      again with the pole at the best-shaped face the centred map puts near the north pole,
//      and kept if it collapses no more faces.
#pragma once

#include <optional>
#include <vector>

#include "mesh/mesh_edges.h"
#include "mesh/prepared_mesh.h"
#include "solvers/laplacian_solver.h"
#include "sphere/mobius_centering.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {

struct Genus0Result {
  std::vector<PlaneValue> values;
  int pole_face = -1, raised_weights = 0;
  // `values` centred (mobius_centering.h), where choosing the pole centred them already.
  std::optional<CentredValues> centred;
};

Genus0Result best_genus0_map(const PreparedMesh &prepared, SolverKind solver, int pole_face);

} // namespace meromorph
