#include "mesh/cotan_laplacian.h"

namespace meromorph {

std::vector<double> cotan_weights(const Mesh &mesh, const MeshEdges &edges) {
  std::vector<double> weights(edges.edge_count(), 0.0);
  for (size_t f = 0; f < mesh.face.size(); ++f) {
    const MeshFace &face = mesh.face[f];
    for (int k = 0; k < 3; ++k) {
      // The angle at corner k+2 is opposite side k (corners k, k+1).
      const Point3 &apex = face.cP((k + 2) % 3);
      const Point3 u = face.cP(k) - apex, v = face.cP((k + 1) % 3) - apex;
      weights[edges.face_edges[f][k]] += 0.5 * (u * v) / (u ^ v).Norm();
    }
  }
  return weights;
}

Eigen::SparseMatrix<double> cotan_laplacian(int vertex_count, const MeshEdges &edges,
                                            const std::vector<double> &weights) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(size_t(edges.edge_count()) * 4);
  for (int e = 0; e < edges.edge_count(); ++e) {
    const int i = edges.vertices[e][0], j = edges.vertices[e][1];
    const double w = weights[e];
    entries.emplace_back(i, i, w);
    entries.emplace_back(j, j, w);
    entries.emplace_back(i, j, -w);
    entries.emplace_back(j, i, -w);
  }
  Eigen::SparseMatrix<double> laplacian(vertex_count, vertex_count);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  return laplacian;
}

Eigen::VectorXd laplacian_of_differences(const MeshEdges &edges, const std::vector<double> &weights,
                                         const Eigen::VectorXd &x) {
  Eigen::VectorXd result = Eigen::VectorXd::Zero(x.size());
  for (int e = 0; e < edges.edge_count(); ++e) {
    const int i = edges.vertices[e][0], j = edges.vertices[e][1];
    const double flow = weights[size_t(e)] * (x[i] - x[j]);
    result[i] += flow;
    result[j] -= flow;
  }
  return result;
}

} // namespace meromorph
