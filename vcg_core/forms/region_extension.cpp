#include "forms/region_extension.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace meromorph {

Eigen::VectorXcd harmonic_extension_in_region(const PreparedMesh &prepared,
                                              const std::vector<double> &weights,
                                              const std::vector<char> &free,
                                              const Eigen::VectorXcd &values) {
  const MeshEdges &edges = prepared.edges;
  std::vector<int> free_vertices;
  for (size_t v = 0; v < free.size(); ++v)
    if (free[v]) free_vertices.push_back(int(v));
  Eigen::VectorXcd out = values;
  if (free_vertices.empty()) return out;
  std::vector<int> unknown(free.size(), -1);
  for (size_t i = 0; i < free_vertices.size(); ++i)
    unknown[size_t(free_vertices[i])] = int(i);
  const long m = long(free_vertices.size());
  auto neighbour = [&](int e, int v) {
    return edges.vertices[size_t(e)][0] == v ? edges.vertices[size_t(e)][1]
                                             : edges.vertices[size_t(e)][0];
  };
  std::vector<Eigen::Triplet<double>> entries;
  for (long i = 0; i < m; ++i) {
    const int v = free_vertices[size_t(i)];
    for (int e : prepared.edges_at_vertex[size_t(v)]) {
      const int j = unknown[size_t(neighbour(e, v))];
      entries.emplace_back(i, i, weights[size_t(e)]);
      if (j >= 0) entries.emplace_back(i, j, -weights[size_t(e)]);
    }
  }
  Eigen::SparseMatrix<double> laplacian(m, m);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factored(laplacian);
  if (factored.info() != Eigen::Success) return out;
  // The residual at the free vertices, summed over edge differences (exact where values crowd).
  auto residual = [&] {
    Eigen::MatrixXd r(m, 2);
    for (long i = 0; i < m; ++i) {
      const int v = free_vertices[size_t(i)];
      std::complex<double> sum = 0;
      for (int e : prepared.edges_at_vertex[size_t(v)])
        sum += weights[size_t(e)] * (out[neighbour(e, v)] - out[v]);
      r(i, 0) = sum.real();
      r(i, 1) = sum.imag();
    }
    return r;
  };
  for (int v : free_vertices)
    out[v] = 0;
  for (int step = 0; step < 2; ++step) { // the solve, then one step of refinement
    const Eigen::MatrixXd change = factored.solve(residual());
    if (factored.info() != Eigen::Success || !change.allFinite()) return values;
    for (long i = 0; i < m; ++i)
      out[free_vertices[size_t(i)]] += std::complex<double>(change(i, 0), change(i, 1));
  }
  return out;
}

} // namespace meromorph
