// Preconditioned conjugate gradients on a Hermitian positive definite sparse system, which can
// stop at one tolerance and go on to a finer one as if it had never stopped.
//
// In:  the system's matrix H as its lower triangle (compressed, column-major, as Eigen and CHOLMOD
//      keep it), the right side r, a start, and the preconditioner's kind: clusters of stiffly
//      coupled unknowns (solvers/cluster_jacobi.h) or the diagonal alone.
// Out: `advance(tolerance)`: steps from where the last call stopped until |r - H x| <= tolerance
//      |r| (true), or until `most_steps` steps in all (false); `solution()` the x reached. A
//      screening pass to 1e-3 followed by a pass to 1e-6 takes the steps of one pass to 1e-6 and
//      ends at the same x: the search direction is kept between the calls (restarted from x alone,
//      conjugate gradients lose it and take nearly as many steps again: 28 to 40 against 36 to 40
//      on raw marching cubes with needles).
#pragma once

#include <complex>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solvers/cluster_jacobi.h"

namespace meromorph {

class HermitianConjugateGradients {
public:
  using Complex = std::complex<double>;
  enum class Preconditioner { clusters, diagonal };

  // (`lower` is taken over, its arrays swapped in: Eigen 3.4's SparseMatrix has no move
  // constructor, and a copy of a chart's matrix at 178k vertices was 9 MB more at the peak.)
  HermitianConjugateGradients(Eigen::SparseMatrix<Complex> &&lower, Eigen::VectorXcd right,
                              Eigen::VectorXcd start, Preconditioner kind);
  bool advance(double tolerance, int most_steps);
  const Eigen::VectorXcd &solution() const { return x_; }
  int steps() const { return steps_; }
  const Eigen::SparseMatrix<Complex> &lower() const { return lower_; }
  const Eigen::VectorXcd &right() const { return right_; }

private:
  // y = H p, from the lower triangle: each stored entry below the diagonal used for both.
  void multiply(const Eigen::VectorXcd &p, Eigen::VectorXcd &y) const;

  Eigen::SparseMatrix<Complex> lower_;
  Eigen::VectorXcd right_;
  ClusterJacobi preconditioner_;
  Eigen::VectorXcd x_, residual_, direction_, product_;
  double right_norm2_ = 0, residual_norm2_ = 0;
  double previous_rz_ = 0; // r.z of the step before (0: no direction yet)
  int steps_ = 0;
};

} // namespace meromorph
