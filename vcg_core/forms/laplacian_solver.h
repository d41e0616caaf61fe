// Factor the cotangent Laplacian once, solve many times.
//
// In:  the V x V cotangent Laplacian of a connected mesh (singular: its kernel is the constants)
//      and which factorization to use.
// Out: a solver for L x = b at the free vertices, with x = 0 at the pinned vertices (default:
// vertex
//      0 alone, which with b summing to zero solves the singular system; pinning a set of vertices
//      gives Dirichlet problems: put -L_free,pinned x_pinned into b). The reduced matrix is
//      symmetric positive definite. CHOLMOD's supernodal Cholesky (on OpenBLAS) is the default;
//      Eigen's SimplicialLDLT is there to check it against.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace meromorph {

enum class SolverKind { cholmod, eigen_ldlt };

SolverKind solver_from_name(const std::string &name); // "cholmod" or "ldlt"
const char *solver_name(SolverKind kind);

class LaplacianSolver {
public:
  virtual ~LaplacianSolver() = default;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd &right_hand_side) const = 0;
};

std::unique_ptr<LaplacianSolver> factor_laplacian(const Eigen::SparseMatrix<double> &laplacian,
                                                  SolverKind kind = SolverKind::cholmod,
                                                  const std::vector<int> &pinned = {0});

} // namespace meromorph
