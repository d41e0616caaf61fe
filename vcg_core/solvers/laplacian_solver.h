// Factor the cotangent Laplacian once, solve many times.
//
// In:  the V x V cotangent Laplacian of a connected mesh (singular: its kernel is the constants),
//      which factorization to use, the pinned vertices and, optionally, the order in which to
//      eliminate the free ones.
// Out: a solver for L x = b at the free vertices, with x = 0 at the pinned vertices (default:
//      vertex 0 alone, which with b summing to zero solves the singular system; pinning a set of
//      vertices gives Dirichlet problems: put -L_free,pinned x_pinned into b). The reduced matrix
//      is symmetric positive definite. CHOLMOD's supernodal Cholesky (on OpenBLAS, fill-reducing
//      ordering AMD, METIS's nested dissection from two million unknowns: solvers/metis_order.h) is
//      the default; Eigen's SimplicialLDLT is there to check it against.
//      Several right-hand sides at once (`solve_columns`) share one pass over the factor. The
//      elimination order of a factorization can be handed to the next one on a subset of the
//      vertices: the order a good ordering induces on a principal submatrix fills in no more than
//      the whole matrix did, and the ordering (about a fifth of the factorization) is not computed
//      again.
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
  Eigen::VectorXd solve(const Eigen::VectorXd &right_hand_side) const;
  // Column by column: V x k in, V x k out.
  virtual Eigen::MatrixXd solve_columns(const Eigen::MatrixXd &right_hand_sides) const = 0;
  // The same, the right-hand sides released as soon as they are read: with many columns on a
  // large mesh, two V x k arrays at a time instead of five (CHOLMOD's supernodal solves in place
  // on the permuted columns).
  virtual Eigen::MatrixXd solve_columns_releasing(Eigen::MatrixXd &&right_hand_sides) const;
  // The free vertices in the order the factorization eliminated them.
  virtual std::vector<int> elimination_order() const = 0;
  // The system of the free vertices eliminated first alone, the last `last_count` of
  // elimination_order() pinned at 0 too: the factor's leading block is that system's factor, so
  // no new factorization (CHOLMOD; the others throw std::logic_error).
  virtual Eigen::MatrixXd solve_columns_without_last(const Eigen::MatrixXd &right_hand_sides,
                                                     int last_count) const;
};

// `elimination_order` (empty: the solver's own ordering) lists vertices; the free ones among them,
// which must be all of them, are eliminated in that order (CHOLMOD; Eigen's LDL^T keeps its own).
std::unique_ptr<LaplacianSolver> factor_laplacian(const Eigen::SparseMatrix<double> &laplacian,
                                                  SolverKind kind = SolverKind::cholmod,
                                                  const std::vector<int> &pinned = {0},
                                                  const std::vector<int> &elimination_order = {});
// An elimination order (as above) of the free vertices that eliminates those flagged in
// `eliminate_last` after all others: CHOLMOD's CAMD, minimum degree within both groups. Empty
// where CAMD fails (the factorization then orders by itself).
std::vector<int> elimination_order_with_last(const Eigen::SparseMatrix<double> &laplacian,
                                             const std::vector<int> &pinned,
                                             const std::vector<char> &eliminate_last);
// The same, the Laplacian released before the factor is allocated (its upper triangle is copied,
// and that copy released once CHOLMOD has permuted it).
std::unique_ptr<LaplacianSolver> factor_laplacian(Eigen::SparseMatrix<double> &&laplacian,
                                                  SolverKind kind = SolverKind::cholmod,
                                                  const std::vector<int> &pinned = {0},
                                                  const std::vector<int> &elimination_order = {});

} // namespace meromorph
