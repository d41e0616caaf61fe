#include "solvers/reweighted_solve.h"

#include <algorithm>

namespace meromorph {

ReweightedSolve::ReweightedSolve(const LaplacianSolver &factor, int vertex_count,
                                 const std::vector<int> &pinned, const MeshEdges &edges,
                                 const std::vector<double> &before,
                                 const std::vector<double> &after, int most_vertices)
    : factor_(factor) {
  std::vector<char> is_pinned(size_t(vertex_count), 0);
  for (int v : pinned)
    is_pinned[size_t(v)] = 1;
  std::vector<int> changed;
  for (int e = 0; e < edges.edge_count(); ++e)
    if (before[size_t(e)] != after[size_t(e)]) {
      changed.push_back(e);
      for (int v : edges.vertices[size_t(e)])
        if (!is_pinned[size_t(v)]) touched_.push_back(v);
    }
  std::sort(touched_.begin(), touched_.end());
  touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
  if (int(touched_.size()) > most_vertices) {
    usable_ = false;
    return;
  }
  const long m = long(touched_.size());
  if (m == 0) return;
  auto slot = [&](int v) {
    const auto it = std::lower_bound(touched_.begin(), touched_.end(), v);
    return it != touched_.end() && *it == v ? long(it - touched_.begin()) : -1L;
  };
  // Each changed edge (a, b) adds delta (e_a - e_b)(e_a - e_b)^T; a pinned end's row and column
  // are not in the factored block.
  change_ = Eigen::MatrixXd::Zero(m, m);
  for (int e : changed) {
    const double delta = after[size_t(e)] - before[size_t(e)];
    const long a = slot(edges.vertices[size_t(e)][0]), b = slot(edges.vertices[size_t(e)][1]);
    if (a >= 0) change_(a, a) += delta;
    if (b >= 0) change_(b, b) += delta;
    if (a >= 0 && b >= 0) {
      change_(a, b) -= delta;
      change_(b, a) -= delta;
    }
  }
  Eigen::MatrixXd units = Eigen::MatrixXd::Zero(vertex_count, m);
  for (long k = 0; k < m; ++k)
    units(touched_[size_t(k)], k) = 1;
  touched_solved_ = factor_.solve_columns(units);
  Eigen::MatrixXd at_touched(m, m);
  for (long k = 0; k < m; ++k)
    at_touched.row(k) = touched_solved_.row(touched_[size_t(k)]);
  capacitance_.compute(Eigen::MatrixXd::Identity(m, m) + change_ * at_touched);
}

Eigen::MatrixXd ReweightedSolve::solve_columns(const Eigen::MatrixXd &b) const {
  Eigen::MatrixXd y = factor_.solve_columns(b);
  if (touched_.empty()) return y;
  Eigen::MatrixXd at_touched(long(touched_.size()), y.cols());
  for (size_t k = 0; k < touched_.size(); ++k)
    at_touched.row(long(k)) = y.row(touched_[k]);
  y -= touched_solved_ * capacitance_.solve(change_ * at_touched);
  return y;
}

} // namespace meromorph
