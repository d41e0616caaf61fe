// Untangling isolated folds of sliver faces.
//
// In:  a mesh, a unit-sphere position per vertex (modified in place), and vertices not to move
//      (branch points).
// Out: a face with a corner near 180 degrees (a sliver) has an image whose great-circle triangle
//      can turn over under the Moebius centring, which bends straight edges into circles; such a
//      fold is not a fold of the conformal map. Each folded face away from the fixed vertices has
//      one of its corners moved to the normalized mean of its one-ring's images, or else into its
//      star's kernel (star_kernel.h: where no face around it is turned over), if that leaves
//      fewer folded faces around it. A face still folded then (an obtuse corner on a noisy mesh,
//      next to a branch vertex too) has the region within 1 to 5 rings of it re-embedded in the
//      gnomonic chart at its centre by mean-value weights of the surface (Floater), the region's
//      rim and the fixed vertices kept, if no face of the region is folded afterwards; beside a
//      branch vertex, else, the rings around its star re-embedded about its value
//      (branch_star.h), if that unfolds them. Returns
//      how many vertices or regions were moved (reported to the user).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"
#include "mesh/prepared_mesh.h"

namespace meromorph {

int untangle_folds(const PreparedMesh &prepared, std::vector<Eigen::Vector3d> &sphere,
                   const std::vector<int> &fixed);

} // namespace meromorph
