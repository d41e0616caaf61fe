// The harmonic extension into a small region, the rest of the mesh held.
//
// In:  the prepared mesh (its edges and the edges at each vertex), edge weights (a cotangent
//      Laplacian's, positive definite once anything is held), a flag per vertex for the free
//      ones, and complex values per vertex (those at held vertices are kept).
// Out: the values with the free vertices' replaced by the solution of sum_e w_e (z_w - z_v) = 0
//      at each free vertex v. Only the free vertices' rows are assembled and factored (Eigen's
//      simplicial LDLT with its AMD order), so the work is the region's, not the mesh's; one step
//      of iterative refinement on the residual summed over edge differences keeps a region that
//      crowds into a tiny spot accurate relative to its own size. Unchanged where no vertex is
//      free; where the factorization fails, the values as given.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "mesh/prepared_mesh.h"

namespace meromorph {

Eigen::VectorXcd harmonic_extension_in_region(const PreparedMesh &prepared,
                                              const std::vector<double> &weights,
                                              const std::vector<char> &free,
                                              const Eigen::VectorXcd &values);

} // namespace meromorph
