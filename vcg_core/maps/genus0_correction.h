// Genus 0: the pinned-pole harmonic map made conformal, far from the pole and near it.
//
// In:  a closed genus-0 prepared mesh, the edge weights the pinned-pole map was solved with,
//      the solver, and that map (genus0_map.h: finite values, the puncture face's corners pinned).
// Out: the corrected values, or the input values where a correction would fold a face. Why:
//      with three corners pinned the harmonic solution is z = A f + B conj(f) away from the pole,
//      f the conformal map: a global affine shear (its per-face Beltrami ratio
//      nu = z_conj(w) / conj(z_w) is nearly constant), which carries most of the angle error. So:
//      1. the shear goes: nu = the component-wise median of the per-face ratios (the puncture face
//         and the faces at the 10% of vertices farthest out left out), z <- z - nu conj(z), an
//         orientation-preserving affine map that is exact for z = A f + B conj(f);
//      2. the pole region is solved again (FLASH's south-pole step, Choi, Lam, Lui 2015): the 10%
//         of vertices nearest the median value z_s are pinned at zeta = 1 / (z - z_s), the rest is
//         the harmonic extension in that chart (the puncture face is an ordinary face there), and
//         mapped back;
//      With CHOLMOD the step needs no factorization of its own where the pinned-pole map's
//      factor eliminated a predicted cap last (south_cap_prediction.h) that holds at least half
//      of the cap above: that cap is pinned instead, solved with the factor's leading block and
//      the puncture corners bordered in (leading_block_solve.h); the factor's weights are the
//      map's before any were raised, so the region around raised weights (and around faces the
//      result folds) is solved again locally, as genus0_best_map.h does for the map itself.
//      Otherwise the step factors its Laplacian, in the order the pinned-pole map's chose.
//      (Solving the half nearest z_s again with the rest pinned, as a third step, was measured:
//      0.13 -> 0.05 degrees on an icosphere, no gain or a loss on real meshes, one more
//      factorization.)
//      Folds are checked in whichever chart each face lies in (|z| < 1: z, else 1 / z); a step that
//      folds a face is not taken.
#pragma once

#include <vector>

#include "maps/genus0_map.h"
#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"
#include "mesh/prepared_mesh.h"
#include "solvers/laplacian_solver.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {

// The south-pole step's cap: the share of vertices nearest the median (component by component)
// of the finite values.
constexpr double south_cap_share = 0.1;
std::vector<int> south_cap(const std::vector<PlaneValue> &values);

struct Genus0Correction {
  std::vector<PlaneValue> values;
  Complex shear{0, 0}; // nu, removed in step 1
  int steps_taken = 0; // 0 to 2
};

// `elimination_order`: the pinned-pole map's (Genus0Map), reused by the south-pole step's
// factorization; `cap_last` (may be empty): the pinned-pole map's factor with a predicted cap
// eliminated last (south_cap_prediction.h), which the south-pole step then solves with and no
// factorization, the predicted cap pinned, where it holds at least half of the map's own cap.
Genus0Correction correct_genus0_map(const PreparedMesh &prepared,
                                    const std::vector<double> &weights, SolverKind solver,
                                    int pole_face, const std::vector<PlaneValue> &pinned_map,
                                    const std::vector<int> &elimination_order,
                                    const CapLastFactor &cap_last);

// Faces whose image on the sphere (the chord triangle of the corners' inverse stereographic
// images) is turned over or flat; faces below what doubles resolve are not counted.
std::vector<int> folded_plane_faces(const FaceIncidence &in, const std::vector<PlaneValue> &values);

} // namespace meromorph
