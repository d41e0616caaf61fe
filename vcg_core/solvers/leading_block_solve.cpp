#include "solvers/leading_block_solve.h"

#include <Eigen/LU>

namespace meromorph {

// With G the leading block's vertices and K the freed ones:
//   L_GG x_G + L_GK x_K = b_G,  L_KG x_G + L_KK x_K = b_K
// gives x_G = y - W x_K with y = L_GG^-1 b_G, W = L_GG^-1 L_GK, and
// (L_KK - L_KG W) x_K = b_K - L_KG y.
LeadingBlockSolve::LeadingBlockSolve(const LaplacianSolver &factor,
                                     const Eigen::SparseMatrix<double> &laplacian, int last_count,
                                     std::vector<int> freed)
    : factor_(factor), laplacian_(laplacian), last_count_(last_count), freed_(std::move(freed)) {}

Eigen::MatrixXd LeadingBlockSolve::laplacian_at_freed(const Eigen::MatrixXd &x) const {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(long(freed_.size()), x.cols());
  for (size_t k = 0; k < freed_.size(); ++k) // L is symmetric: row = column
    for (Eigen::SparseMatrix<double>::InnerIterator it(laplacian_, freed_[k]); it; ++it)
      out.row(long(k)) += it.value() * x.row(it.row());
  return out;
}

Eigen::MatrixXd LeadingBlockSolve::solve_columns(const Eigen::MatrixXd &b) const {
  const long m = long(freed_.size());
  if (m == 0) return factor_.solve_columns_without_last(b, last_count_);
  Eigen::MatrixXd x;
  if (bordered_) {
    x = factor_.solve_columns_without_last(b, last_count_);
  } else {
    // L's columns at the freed vertices beside b (rows the factor pins or leaves out are not
    // read): one pass over the factor for both.
    Eigen::MatrixXd both = Eigen::MatrixXd::Zero(b.rows(), b.cols() + m);
    both.leftCols(b.cols()) = b;
    for (long k = 0; k < m; ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(laplacian_, freed_[size_t(k)]); it; ++it)
        both(it.row(), b.cols() + k) = it.value();
    both = factor_.solve_columns_without_last(both, last_count_);
    freed_columns_solved_ = both.rightCols(m);
    x = both.leftCols(b.cols());
    Eigen::MatrixXd schur = -laplacian_at_freed(freed_columns_solved_);
    for (long j = 0; j < m; ++j)
      for (long k = 0; k < m; ++k)
        schur(j, k) += laplacian_.coeff(freed_[size_t(j)], freed_[size_t(k)]);
    schur_inverse_ = schur.inverse();
    bordered_ = true;
  }
  Eigen::MatrixXd at_freed(m, b.cols());
  for (size_t k = 0; k < freed_.size(); ++k)
    at_freed.row(long(k)) = b.row(freed_[k]);
  const Eigen::MatrixXd x_freed = schur_inverse_ * (at_freed - laplacian_at_freed(x));
  x -= freed_columns_solved_ * x_freed;
  for (size_t k = 0; k < freed_.size(); ++k)
    x.row(freed_[k]) = x_freed.row(long(k));
  return x;
}

} // namespace meromorph
