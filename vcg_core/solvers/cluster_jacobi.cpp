#include "solvers/cluster_jacobi.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>

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

// Entry (i, j), i >= j, of an m x m block's lower triangle packed column by column (column j's
// rows j to m - 1 after columns 0 to j - 1): m (m + 1) / 2 entries, the upper triangle being
// their conjugates.
inline int packed(int i, int j, int m) {
  return j * m - j * (j - 1) / 2 + (i - j);
}

// A Hermitian positive definite block (its lower triangle packed: `packed`) replaced by its
// inverse's: A = L L^H (Cholesky), W = L^-1, A^-1 = W^H W, about m^3 / 2 complex
// multiply-adds, a third of what Eigen's LLT solved against the identity took (the blocks of a
// raw marching-cubes genus-10 mesh with needles, 178k vertices, six charts: 143-183 -> 61-66 ms;
// the same map to the byte). False, the block untouched, where a pivot is not positive (the block
// is not positive definite to rounding).
bool inverted_in_place(std::complex<double> *block, int m) {
  using Scalar = std::complex<double>;
  if (m == 1) { // Jacobi's 1 / a_ii
    block[0] = Scalar(1) / block[0];
    return true;
  }
  std::array<Scalar, size_t(cluster_size * cluster_size)> l{}, w{};
  for (int j = 0; j < m; ++j) {
    double pivot = block[packed(j, j, m)].real();
    for (int k = 0; k < j; ++k)
      pivot -= std::norm(l[size_t(j + m * k)]);
    if (!(pivot > 0)) return false;
    const double diagonal = std::sqrt(pivot);
    l[size_t(j + m * j)] = diagonal;
    for (int i = j + 1; i < m; ++i) {
      Scalar sum = block[packed(i, j, m)];
      for (int k = 0; k < j; ++k)
        sum -= l[size_t(i + m * k)] * std::conj(l[size_t(j + m * k)]);
      l[size_t(i + m * j)] = sum / diagonal;
    }
  }
  for (int j = 0; j < m; ++j) {
    w[size_t(j + m * j)] = 1.0 / l[size_t(j + m * j)].real();
    for (int i = j + 1; i < m; ++i) {
      Scalar sum(0, 0);
      for (int k = j; k < i; ++k)
        sum += l[size_t(i + m * k)] * w[size_t(k + m * j)];
      w[size_t(i + m * j)] = -sum / l[size_t(i + m * i)].real();
    }
  }
  for (int j = 0; j < m; ++j)
    for (int i = j; i < m; ++i) {
      Scalar sum(0, 0);
      for (int k = i; k < m; ++k)
        sum += std::conj(w[size_t(k + m * i)]) * w[size_t(k + m * j)];
      block[packed(i, j, m)] = sum;
    }
  return true;
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
    block_start_[size_t(c) + 1] = block_start_[size_t(c)] + m * (m + 1) / 2;
  }
  inverses_.assign(block_start_.back(), Scalar(0, 0));
  for (int j = 0; j < n; ++j) {
    const int c = cluster_of[size_t(j)];
    const int m = cluster_start_[size_t(c) + 1] - cluster_start_[size_t(c)];
    Scalar *block = &inverses_[block_start_[size_t(c)]];
    for (int k = a.outer[j]; k < a.outer[j + 1]; ++k) {
      const int i = a.inner[k];
      if (cluster_of[size_t(i)] != c) continue;
      // (places follow the unknowns' order: an entry of A's lower triangle is the block's)
      const int row = place[size_t(i)], column = place[size_t(j)];
      if (row >= column)
        block[packed(row, column, m)] = a.values[k];
      else
        block[packed(column, row, m)] = std::conj(a.values[k]);
    }
  }
  for (int c = 0; c < clusters; ++c) {
    const int m = cluster_start_[size_t(c) + 1] - cluster_start_[size_t(c)];
    Scalar *block = &inverses_[block_start_[size_t(c)]];
    if (!inverted_in_place(block, m)) { // (rounding can leave a nearly singular block
      for (int j = 0; j < m; ++j)       // indefinite: Jacobi there)
        for (int i = j; i < m; ++i)
          block[packed(i, j, m)] = i == j ? Scalar(1) / block[packed(i, i, m)] : Scalar(0, 0);
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
      for (int j = 0; j <= i; ++j)
        sum += inverse[packed(i, j, m)] * r[member[j]];
      for (int j = i + 1; j < m; ++j)
        sum += std::conj(inverse[packed(j, i, m)]) * r[member[j]];
      z[member[i]] = sum;
    }
  }
}

} // namespace meromorph
