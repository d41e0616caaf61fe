// A preconditioner for Eigen's ConjugateGradient on Hermitian positive definite sparse systems
// whose unknowns come in stiffly coupled clusters: the ends of a needle's short side, the
// vertices marching cubes puts next to one another. Jacobi's preconditioner leaves such a
// system stiff (706 steps on a raw marching-cubes genus-10 chart against 7 on a remeshed one);
// the clusters' own blocks take the stiffness out (17 steps).
//
// In:  the system's matrix A: its lower triangle or both (compressed, column-major).
// Out: z = B^-1 r, with B block diagonal: one block per cluster of unknowns joined by couplings
//      |a_ij| > cluster_coupling * min(a_ii, a_jj) (the share of the smaller diagonal that the
//      coupling makes: an unknown held mostly by one neighbour moves with it, also where that
//      neighbour is held stiffly by a third, as a needle's far corner beside two close vertices),
//      the strongest first, at most cluster_size unknowns a cluster; each block is A's own
//      principal submatrix (positive definite as A is), so B is too. An unknown alone is
//      Jacobi's preconditioner, 1 / a_ii.
//      `build(A, false)`: every unknown alone (Jacobi's preconditioner). `solve_into` writes z into
//      a vector of the right size (no allocation per step).
//      `stiffly_coupled(A)`: whether some coupling |a_ij| / sqrt(a_ii a_jj) exceeds
//      stiff_coupling (where none does, Jacobi alone converges as fast).
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace meromorph {

// Measured on the charts of raw marching cubes with and without needles (genus 6 and 10): shares
// from 0.15 and clusters of 16 took the least time (genus-6 raw with needles, 62k vertices: 30 to
// 39 steps, where |a_ij| / sqrt(a_ii a_jj) > 0.15 and clusters of 8 took 130 to 145; genus-10
// raw: 15 against 17; shares from 0.1: 10% fewer steps, 50% more time per step; clusters of 12:
// 30% more steps).
constexpr double cluster_coupling = 0.15, stiff_coupling = 0.5;
constexpr int cluster_size = 16;

// A's columns as CHOLMOD and Eigen keep them: column j's rows and values from outer[j] to
// outer[j + 1].
struct CompressedColumns {
  int size;
  const int *outer, *inner;
  const std::complex<double> *values;
};

bool stiffly_coupled(const CompressedColumns &a);

class ClusterJacobi {
public:
  using Scalar = std::complex<double>;
  using RealScalar = double;
  using StorageIndex = int;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic };

  template <class Matrix> ClusterJacobi &analyzePattern(const Matrix &) { return *this; }
  template <class Matrix> ClusterJacobi &factorize(const Matrix &a) { return compute(a); }
  template <class Matrix> ClusterJacobi &compute(const Matrix &a) {
    eigen_assert(a.isCompressed());
    build({int(a.rows()), a.outerIndexPtr(), a.innerIndexPtr(), a.valuePtr()});
    return *this;
  }
  void build(const CompressedColumns &a, bool clustered = true);
  Eigen::VectorXcd solve(const Eigen::VectorXcd &r) const;
  void solve_into(const Eigen::VectorXcd &r, Eigen::VectorXcd &z) const;
  Eigen::ComputationInfo info() const { return Eigen::Success; }

  int cluster_count() const { return int(cluster_start_.size()) - 1; }

private:
  std::vector<int> members_;        // the unknowns, cluster by cluster
  std::vector<int> cluster_start_;  // per cluster its first place in members_; one more at the end
  std::vector<size_t> block_start_; // per cluster its first entry in inverses_
  std::vector<Scalar> inverses_;    // per cluster its block's inverse, its lower triangle packed
};

} // namespace meromorph
