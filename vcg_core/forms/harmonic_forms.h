// Harmonic 1-forms: the closed forms' co-closed representatives.
//
// In:  closed 1-forms omega_j, the mesh's oriented edges, cotangent weights, a factored Laplacian
//      (handed over: it is released as soon as the potentials are solved, before the forms are
//      laid out on the edges, so that the largest array and the forms are never held at once).
// Out: h_j = omega_j - d f_j with L f_j = div(omega_j), so that sum_k w_ik h_j(ik) = 0 at every
//      vertex (co-closed) while h_j stays closed and has omega_j's periods. One solve for all.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "mesh/mesh_edges.h"
#include "solvers/laplacian_solver.h"

namespace meromorph {

// (div form)_k = sum over edges into k of w * form - sum over edges out of k of w * form.
Eigen::VectorXd weighted_divergence(int vertex_count, const MeshEdges &edges,
                                    const std::vector<double> &weights,
                                    const Eigen::VectorXd &form);

// The closed forms are sparse (homology_basis.h: nonzero where a dual loop crosses).
std::vector<Eigen::VectorXd>
harmonic_forms(const std::vector<Eigen::SparseVector<double>> &closed_forms, int vertex_count,
               const MeshEdges &edges, const std::vector<double> &weights,
               std::unique_ptr<LaplacianSolver> solver);

} // namespace meromorph
