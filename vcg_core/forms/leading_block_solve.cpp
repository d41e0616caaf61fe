#include "forms/leading_block_solve.h"

#include <Eigen/LU>

namespace meromorph {

// With G the leading block's vertices and K the freed ones:
//   L_GG x_G + L_GK x_K = b_G,  L_KG x_G + L_KK x_K = b_K
// gives x_G = y - W x_K with y = L_GG^-1 b_G, W = L_GG^-1 L_GK, and
// (L_KK - L_KG W) x_K = b_K - L_KG y.
LeadingBlockSolve::LeadingBlockSolve(const LaplacianSolver &factor,
                                     const Eigen::SparseMatrix<double> &laplacian, int last_count,
                                     std::vector<int> freed)
    : factor_(factor), laplacian_(laplacian), last_count_(last_count), freed_(std::move(freed)) {
  const long m = long(freed_.size());
  Eigen::MatrixXd columns = Eigen::MatrixXd::Zero(laplacian.rows(), m);
  for (long k = 0; k < m; ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(laplacian, freed_[size_t(k)]); it; ++it)
      columns(it.row(), k) = it.value(); // rows the factor pins or leaves out are not read
  freed_columns_solved_ = factor_.solve_columns_without_last(columns, last_count_);
  Eigen::MatrixXd schur = -laplacian_at_freed(freed_columns_solved_);
  for (long j = 0; j < m; ++j)
    for (long k = 0; k < m; ++k)
      schur(j, k) += laplacian.coeff(freed_[size_t(j)], freed_[size_t(k)]);
  schur_inverse_ = schur.inverse();
}

Eigen::MatrixXd LeadingBlockSolve::laplacian_at_freed(const Eigen::MatrixXd &x) const {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(long(freed_.size()), x.cols());
  for (size_t k = 0; k < freed_.size(); ++k) // L is symmetric: row = column
    for (Eigen::SparseMatrix<double>::InnerIterator it(laplacian_, freed_[k]); it; ++it)
      out.row(long(k)) += it.value() * x.row(it.row());
  return out;
}

Eigen::MatrixXd LeadingBlockSolve::solve_columns(const Eigen::MatrixXd &b) const {
  Eigen::MatrixXd x = factor_.solve_columns_without_last(b, last_count_);
  if (freed_.empty()) return x;
  Eigen::MatrixXd at_freed(long(freed_.size()), b.cols());
  for (size_t k = 0; k < freed_.size(); ++k)
    at_freed.row(long(k)) = b.row(freed_[k]);
  const Eigen::MatrixXd x_freed = schur_inverse_ * (at_freed - laplacian_at_freed(x));
  x -= freed_columns_solved_ * x_freed;
  for (size_t k = 0; k < freed_.size(); ++k)
    x.row(freed_[k]) = x_freed.row(long(k));
  return x;
}

} // namespace meromorph
