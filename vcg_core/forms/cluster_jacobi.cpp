#include "forms/cluster_jacobi.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include <Eigen/Dense>

namespace meromorph {
namespace {

// The diagonal's real parts.
std::vector<double> diagonal_of(const CompressedColumns &a) {
  std::vector<double> diagonal(size_t(a.size), 0.0);
  for (int j = 0; j < a.size; ++j) {
    const int first = a.outer[j]; // (a lower triangle: the diagonal comes first)
    if (first < a.outer[j + 1] && a.inner[first] == j) {
      diagonal[size_t(j)] = a.values[first].real();
      continue;
    }
    for (int k = first; k < a.outer[j + 1]; ++k)
      if (a.inner[k] == j) diagonal[size_t(j)] = a.values[k].real();
  }
  return diagonal;
}

// |a_ij| / sqrt(a_ii a_jj): 1 for two unknowns that move as one, NaN where a diagonal entry is
// not positive (never a stiff coupling then).
double coupling(const std::vector<double> &diagonal, int i, int j, std::complex<double> value) {
  return std::abs(value) / std::sqrt(diagonal[size_t(i)] * diagonal[size_t(j)]);
}

// |a_ij| / min(a_ii, a_jj): the share of the smaller diagonal that the coupling makes (NaN or
// negative where a diagonal entry is not positive: never a cluster's coupling then).
double share(const std::vector<double> &diagonal, int i, int j, std::complex<double> value) {
  return std::sqrt(std::norm(value)) / std::min(diagonal[size_t(i)], diagonal[size_t(j)]);
}

} // namespace

bool stiffly_coupled(const CompressedColumns &a) {
  const std::vector<double> diagonal = diagonal_of(a);
  for (int j = 0; j < a.size; ++j)
    for (int k = a.outer[j]; k < a.outer[j + 1]; ++k)
      if (a.inner[k] != j && coupling(diagonal, a.inner[k], j, a.values[k]) > stiff_coupling)
        return true;
  return false;
}

void ClusterJacobi::build(const CompressedColumns &a, bool clustered) {
  const int n = a.size;
  const std::vector<double> diagonal = diagonal_of(a);
  // The couplings above cluster_coupling, strongest first (ties by position: the same clusters
  // on every run; a coupling stored in both triangles comes twice, side by side).
  std::vector<std::tuple<double, int, int>> strong;
  for (int j = 0; j < n && clustered; ++j)
    for (int k = a.outer[j]; k < a.outer[j + 1]; ++k) {
      const int i = a.inner[k];
      if (i == j) continue;
      const double c = share(diagonal, i, j, a.values[k]);
      if (c > cluster_coupling) strong.emplace_back(-c, std::min(i, j), std::max(i, j));
    }
  std::sort(strong.begin(), strong.end());
  // Clusters by union-find, none above cluster_size.
  std::vector<int> parent(static_cast<size_t>(n)), size(static_cast<size_t>(n), 1);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int x) {
    while (parent[size_t(x)] != x)
      x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
    return x;
  };
  for (const auto &[minus_c, j, i] : strong) {
    int x = root(i), y = root(j);
    if (x == y || size[size_t(x)] + size[size_t(y)] > cluster_size) continue;
    if (x > y) std::swap(x, y); // the smaller index stays the root
    parent[size_t(y)] = x;
    size[size_t(x)] += size[size_t(y)];
  }
  // Clusters in the order of their first unknown, members in increasing order.
  std::vector<int> cluster_of(static_cast<size_t>(n), -1), place(static_cast<size_t>(n));
  cluster_start_.assign(1, 0);
  for (int i = 0; i < n; ++i)
    if (root(i) == i) {
      cluster_of[size_t(i)] = int(cluster_start_.size()) - 1;
      cluster_start_.push_back(cluster_start_.back() + size[size_t(i)]);
    }
  members_.assign(size_t(n), 0);
  std::vector<int> filled(cluster_start_.begin(), cluster_start_.end() - 1);
  for (int i = 0; i < n; ++i) {
    const int c = cluster_of[size_t(root(i))];
    cluster_of[size_t(i)] = c;
    place[size_t(i)] = filled[size_t(c)] - cluster_start_[size_t(c)];
    members_[size_t(filled[size_t(c)]++)] = i;
  }
  const int clusters = cluster_count();
  block_start_.assign(size_t(clusters) + 1, 0);
  for (int c = 0; c < clusters; ++c) {
    const size_t m = size_t(cluster_start_[size_t(c) + 1] - cluster_start_[size_t(c)]);
    block_start_[size_t(c) + 1] = block_start_[size_t(c)] + m * m;
  }
  inverses_.assign(block_start_.back(), Scalar(0, 0));
  for (int j = 0; j < n; ++j) {
    const int c = cluster_of[size_t(j)];
    const int m = cluster_start_[size_t(c) + 1] - cluster_start_[size_t(c)];
    Scalar *block = &inverses_[block_start_[size_t(c)]];
    for (int k = a.outer[j]; k < a.outer[j + 1]; ++k) {
      const int i = a.inner[k];
      if (cluster_of[size_t(i)] != c) continue;
      block[place[size_t(i)] + m * place[size_t(j)]] = a.values[k];
      if (i != j) block[place[size_t(j)] + m * place[size_t(i)]] = std::conj(a.values[k]);
    }
  }
  for (int c = 0; c < clusters; ++c) {
    const int m = cluster_start_[size_t(c) + 1] - cluster_start_[size_t(c)];
    Scalar *block = &inverses_[block_start_[size_t(c)]];
    if (m == 1) {
      block[0] = Scalar(1) / block[0];
      continue;
    }
    // (On the stack: no allocation per cluster.)
    using Block = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor,
                                cluster_size, cluster_size>;
    Eigen::Map<Eigen::MatrixXcd> matrix(block, m, m);
    const Eigen::LLT<Block> factor{Block(matrix)};
    if (factor.info() == Eigen::Success) {
      matrix = factor.solve(Block::Identity(m, m));
    } else { // (rounding can leave a nearly singular block indefinite: Jacobi there)
      const Block inverse_diagonal = matrix.diagonal().cwiseInverse().asDiagonal();
      matrix = inverse_diagonal;
    }
  }
}

Eigen::VectorXcd ClusterJacobi::solve(const Eigen::VectorXcd &r) const {
  Eigen::VectorXcd z(r.size());
  solve_into(r, z);
  return z;
}

void ClusterJacobi::solve_into(const Eigen::VectorXcd &r, Eigen::VectorXcd &z) const {
  const int clusters = cluster_count();
  for (int c = 0; c < clusters; ++c) {
    const int first = cluster_start_[size_t(c)];
    const int m = cluster_start_[size_t(c) + 1] - first;
    const int *member = &members_[size_t(first)];
    const Scalar *inverse = &inverses_[block_start_[size_t(c)]];
    for (int i = 0; i < m; ++i) {
      Scalar sum(0, 0);
      for (int j = 0; j < m; ++j)
        sum += inverse[i + m * j] * r[member[j]];
      z[member[i]] = sum;
    }
  }
}

} // namespace meromorph
