#include "solvers/hermitian_cg.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace meromorph {

HermitianConjugateGradients::HermitianConjugateGradients(Eigen::SparseMatrix<Complex> &&lower,
                                                         Eigen::VectorXcd right,
                                                         Eigen::VectorXcd start,
                                                         Preconditioner kind)
    : right_(std::move(right)), x_(std::move(start)) {
  lower_.swap(lower);
  lower_.makeCompressed();
  preconditioner_.build(
      {int(lower_.rows()), lower_.outerIndexPtr(), lower_.innerIndexPtr(), lower_.valuePtr()},
      kind == Preconditioner::clusters);
  const long n = lower_.rows();
  residual_.resize(n);
  product_.resize(n);
  multiply(x_, product_);
  residual_ = right_ - product_;
  right_norm2_ = right_.squaredNorm();
  residual_norm2_ = residual_.squaredNorm();
}

void HermitianConjugateGradients::multiply(const Eigen::VectorXcd &p, Eigen::VectorXcd &y) const {
  const int n = int(lower_.rows());
  const int *outer = lower_.outerIndexPtr(), *inner = lower_.innerIndexPtr();
  const Complex *values = lower_.valuePtr();
  const double *in = reinterpret_cast<const double *>(p.data());
  double *out = reinterpret_cast<double *>(y.data());
  // Columns from the last: entry y_j is set at column j (everything added to it comes from the
  // columns before it, which come after), so y needs no clearing.
  for (int j = n - 1; j >= 0; --j) {
    const double pr = in[2 * j], pi = in[2 * j + 1];
    double sr = 0, si = 0; // row j's sum over the column's entries, conjugated
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      const int i = inner[k];
      const double ar = values[k].real(), ai = values[k].imag();
      if (i == j) {
        sr += ar * pr - ai * pi;
        si += ar * pi + ai * pr;
        continue;
      }
      out[2 * i] += ar * pr - ai * pi; // H(i, j) p_j
      out[2 * i + 1] += ar * pi + ai * pr;
      const double qr = in[2 * i], qi = in[2 * i + 1]; // conj(H(i, j)) p_i
      sr += ar * qr + ai * qi;
      si += ar * qi - ai * qr;
    }
    out[2 * j] = sr;
    out[2 * j + 1] = si;
  }
}

bool HermitianConjugateGradients::advance(double tolerance, int most_steps) {
  if (right_norm2_ == 0) {
    x_.setZero();
    return true;
  }
  const double threshold =
      std::max(tolerance * tolerance * right_norm2_, std::numeric_limits<double>::min());
  Eigen::VectorXcd z(x_.size());
  while (residual_norm2_ >= threshold) {
    if (steps_ >= most_steps) return false;
    preconditioner_.solve_into(residual_, z);
    const double rz = residual_.dot(z).real();
    if (previous_rz_ == 0)
      direction_ = z;
    else
      direction_ = z + (rz / previous_rz_) * direction_;
    previous_rz_ = rz;
    multiply(direction_, product_);
    const Complex alpha = rz / direction_.dot(product_);
    double norm2 = 0; // x and r moved, |r|^2 summed, in one pass
    for (long i = 0; i < x_.size(); ++i) {
      x_[i] += alpha * direction_[i];
      residual_[i] -= alpha * product_[i];
      norm2 += std::norm(residual_[i]);
    }
    residual_norm2_ = norm2;
    ++steps_;
    if (!std::isfinite(residual_norm2_)) return false;
  }
  return true;
}

} // namespace meromorph
