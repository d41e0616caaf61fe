// The cotangent Laplacian and its edge weights.
//
// In:  a mesh and its oriented edges.
// Out: per-edge weights w_e = (cot alpha + cot beta) / 2 over the two angles opposite the edge,
//      and the V x V matrix L with L_ii = sum_j w_ij and L_ij = -w_ij (the stiffness matrix of
//      piecewise-linear functions: sum_f area_f |grad u|^2 = u^T L u).
//
// Obtuse and near-degenerate triangles: L is the exact Dirichlet energy of piecewise-linear
// functions on any non-degenerate triangle, so it stays positive semi-definite (kernel: the
// constants) even where weights are negative (non-Delaunay edges) or huge (needle triangles).
// The weights are computed as cos/sin = dot / |cross| in double precision and are not clamped:
// clamping would break the identity above, which the harmonic and conjugate forms rely on.
// Zero-area faces, where a cotangent is infinite, are refused earlier by validation.
#pragma once

#include <vector>

#include <Eigen/SparseCore>

#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"

namespace meromorph {

std::vector<double> cotan_weights(const Mesh &mesh, const MeshEdges &edges);

Eigen::SparseMatrix<double> cotan_laplacian(int vertex_count, const MeshEdges &edges,
                                            const std::vector<double> &weights);

// L x summed edge by edge as sum_j w_ij (x_i - x_j): where x varies little about a large value
// (a crowded part of a map), the differences are exact and the result is accurate relative to
// them, unlike the matrix product, whose error is relative to x itself.
Eigen::VectorXd laplacian_of_differences(const MeshEdges &edges, const std::vector<double> &weights,
                                         const Eigen::VectorXd &x);

} // namespace meromorph
