#include "forms/periods.h"

#include <cmath>

#include "common/errors.h"
#include "common/parallel_for.h"

namespace meromorph {

Eigen::MatrixXi wedge_matrix(const std::vector<Eigen::VectorXd> &closed_forms,
                             const MeshEdges &edges, double *largest_rounding) {
  const long n = long(closed_forms.size());
  // The integrals of h_j ^ h_k over the faces, every pair in one pass over the faces.
  const size_t face_count = edges.face_edges.size();
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(n, n);
  const Eigen::MatrixXd integral = chunked_sum(face_count, zero, [&](size_t begin, size_t end) {
    // sum over the sides of (a_s b_{s+1} - a_{s+1} b_s) / 6 = (P - P^T) / 6, P = A^T (A shifted
    // by one side), summed over the chunk's faces first (no allocation per face).
    Eigen::MatrixXd products = zero;
    Eigen::Matrix3Xd sides(3, n), next(3, n); // the forms' values on the sides, counter-clockwise
    for (size_t f = begin; f < end; ++f) {
      for (int side = 0; side < 3; ++side) {
        const int e = edges.face_edges[f][side], sign = edges.face_signs[f][side];
        for (long j = 0; j < n; ++j)
          sides(side, j) = sign * closed_forms[size_t(j)][e];
      }
      next.row(0) = sides.row(1);
      next.row(1) = sides.row(2);
      next.row(2) = sides.row(0);
      products.noalias() += sides.transpose().lazyProduct(next);
    }
    const Eigen::MatrixXd sum = (products - products.transpose()) / 6.0;
    return sum;
  });
  Eigen::MatrixXi wedge = Eigen::MatrixXi::Zero(n, n);
  double worst = 0;
  for (long j = 0; j < n; ++j)
    for (long k = j + 1; k < n; ++k) {
      const double rounded = std::round(integral(j, k));
      worst = std::max(worst, std::abs(integral(j, k) - rounded));
      wedge(j, k) = int(rounded);
      wedge(k, j) = -int(rounded);
    }
  if (largest_rounding) *largest_rounding = worst;
  if (worst > 1e-3)
    throw InternalError("the intersection numbers are not integers (off by " +
                        std::to_string(worst) + ")");
  return wedge;
}

Eigen::MatrixXi symplectic_basis(const Eigen::MatrixXi &wedge) {
  const long n = wedge.rows(), g = n / 2;
  std::vector<Eigen::VectorXi> remaining;
  for (long i = 0; i < n; ++i)
    remaining.push_back(Eigen::VectorXi::Unit(n, i));
  auto form = [&](const Eigen::VectorXi &u, const Eigen::VectorXi &v) { return u.dot(wedge * v); };
  Eigen::MatrixXi basis(n, n);
  for (long k = 0; k < g; ++k) {
    size_t ui = 0, vi = 0;
    bool found = false;
    for (ui = 0; ui < remaining.size() && !found; ++ui)
      for (vi = ui + 1; vi < remaining.size() && !found; ++vi)
        found = std::abs(form(remaining[ui], remaining[vi])) == 1;
    if (!found) throw InternalError("no symplectic pair in the intersection form");
    --ui;
    --vi;
    Eigen::VectorXi u = remaining[ui], v = remaining[vi];
    if (form(u, v) == -1) v = -v;
    remaining.erase(remaining.begin() + long(vi));
    remaining.erase(remaining.begin() + long(ui));
    for (Eigen::VectorXi &w : remaining)
      w = w - form(w, v) * u + form(w, u) * v;
    basis.col(k) = u;
    basis.col(g + k) = v;
  }
  return basis;
}

std::complex<double> reduce_modulus(std::complex<double> tau) {
  if (tau.imag() < 0) tau = -tau;
  for (int step = 0; step < 1000; ++step) {
    tau -= std::round(tau.real());
    if (std::norm(tau) < 1.0 - 1e-15)
      tau = -1.0 / tau;
    else
      break;
  }
  return tau;
}

} // namespace meromorph
