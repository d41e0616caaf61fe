// The genus-0 map as `parameterize` makes it, from the solves of genus0_map.h.
//
// In:  a closed genus-0 mesh (unit scale), prepared (its edges, cotangent weights, faces, areas),
//      the solver and the pole face asked for (-1: automatic).
// Out: the values in the extended plane and the same centred (mobius_centering.h), the pole face
//      used, which weights were solved with and how many of them were raised. The map is solved
//      first with the weights of the intrinsic Delaunay triangulation (intrinsic_delaunay.h:
//      non-negative, where the mesh's cotangent weights are negative at obtuse corners and
//      needles): the pinned-pole map, its shear removed and its pole region solved again
//      (genus0_correction.h); with CHOLMOD one factorization serves the map and the south-pole
//      step (its cap, predicted from a coarse map, eliminated last: south_cap_prediction.h).
//      Each map is judged as it will be written: centred, sliver folds untangled
//      (fold_untangling.h), then faces collapsed below double precision, faces turned over and
//      the mean angle error, in that order. With an automatic pole, where the map is not centred,
//      collapses or folds faces, or its correction did not finish, it is solved again with the
//      pole at the best-shaped face the centred map puts near the north pole, and the better of
//      the two kept. Where the intrinsic weights' map still folds or collapses faces, the mesh's
//      cotangent weights are tried the same way, raised to positive ones near folds (two rings),
//      round by round (solved again within ten rings of them, or on the whole mesh by updating
//      the factor for the few changed weights, or by a new factorization), all of them at the
//      end (with strictly positive weights a map cannot fold), and the better map is kept.
#pragma once

#include <vector>

#include "mesh/prepared_mesh.h"
#include "solvers/laplacian_solver.h"
#include "sphere/mobius_centering.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {

struct Genus0Result {
  std::vector<PlaneValue> values;
  int pole_face = -1, raised_weights = 0;
  bool intrinsic_delaunay = true; // solved with its weights, else the mesh's (some raised)
  CentredValues centred;          // `values` centred (mobius_centering.h)
};

Genus0Result best_genus0_map(const PreparedMesh &prepared, SolverKind solver, int pole_face);

} // namespace meromorph
