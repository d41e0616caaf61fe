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
    // by one side): the faces of a block stacked (three rows each), one matrix product per block
    // (blocks small enough to be reused from the heap, not mapped and cleared afresh).
    Eigen::MatrixXd products = zero;
    Eigen::MatrixXd sides(3 * long(stacked_block), n), next(3 * long(stacked_block), n);
    for (size_t first = begin; first < end; first += stacked_block) {
      const size_t last = std::min(end, first + stacked_block);
      const long rows = 3 * long(last - first);
      for (size_t f = first; f < last; ++f) {
        const long row = 3 * long(f - first);
        for (int side = 0; side < 3; ++side) {
          const int e = edges.face_edges[f][side], sign = edges.face_signs[f][side];
          for (long j = 0; j < n; ++j) {
            const double value = sign * closed_forms[size_t(j)][e];
            sides(row + side, j) = value;
            next(row + (side + 2) % 3, j) = value;
          }
        }
      }
      products.noalias() += sides.topRows(rows).transpose() * next.topRows(rows);
    }
    const Eigen::MatrixXd sum = (products - products.transpose()) / 6.0;
    return sum;
  });
  return rounded_intersections(integral, largest_rounding);
}

Eigen::MatrixXi rounded_intersections(const Eigen::MatrixXd &integral, double *largest_rounding) {
  const long n = integral.rows();
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
