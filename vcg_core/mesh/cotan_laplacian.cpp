#include "mesh/cotan_laplacian.h"

#include <utility>

#include "common/parallel_for.h"

namespace meromorph {

std::vector<double> cotan_weights(const Mesh &mesh, const MeshEdges &edges) {
  // Per edge over the cores: half the cotangent of the corner facing it in each of its faces
  // (the angle at corner k+2 is opposite side k, from corner k to k+1), the faces in the order
  // the edge lists them.
  std::vector<double> weights(edges.edge_count(), 0.0);
  parallel_for(weights.size(), [&](size_t e) {
    for (int f : edges.faces[e]) {
      if (f < 0) continue;
      const MeshFace &face = mesh.face[size_t(f)];
      for (int k = 0; k < 3; ++k) {
        if (edges.face_edges[size_t(f)][size_t(k)] != int(e)) continue;
        const Point3 &apex = face.cP((k + 2) % 3);
        const Point3 u = face.cP(k) - apex, v = face.cP((k + 1) % 3) - apex;
        weights[e] += 0.5 * (u * v) / (u ^ v).Norm();
      }
    }
  });
  return weights;
}

Eigen::SparseMatrix<double> cotan_laplacian(int vertex_count, const MeshEdges &edges,
                                            const std::vector<double> &weights) {
  // Compressed columns built in place (no triplet list, which at a million vertices took twice
  // the matrix's memory and a sort): column v holds the diagonal and one entry per edge at v.
  std::vector<int> start(size_t(vertex_count) + 1, 1); // the diagonal
  start[size_t(vertex_count)] = 0;
  for (const auto &ends : edges.vertices) {
    ++start[size_t(ends[0])];
    ++start[size_t(ends[1])];
  }
  int total = 0;
  for (int &entry : start) {
    const int count = entry;
    entry = total;
    total += count;
  }
  Eigen::SparseMatrix<double> laplacian(vertex_count, vertex_count);
  laplacian.resizeNonZeros(total);
  int *rows = laplacian.innerIndexPtr();
  double *values = laplacian.valuePtr();
  std::vector<int> next(start.begin(), start.end() - 1);
  for (int v = 0; v < vertex_count; ++v) {
    rows[next[size_t(v)]] = v;
    values[next[size_t(v)]++] = 0;
  }
  for (int e = 0; e < edges.edge_count(); ++e) {
    const int i = edges.vertices[size_t(e)][0], j = edges.vertices[size_t(e)][1];
    const double w = weights[size_t(e)];
    values[start[size_t(i)]] += w; // the diagonals come first in their columns
    values[start[size_t(j)]] += w;
    rows[next[size_t(i)]] = j;
    values[next[size_t(i)]++] = -w;
    rows[next[size_t(j)]] = i;
    values[next[size_t(j)]++] = -w;
  }
  // Rows in increasing order within each column (a handful of entries each).
  parallel_for(size_t(vertex_count), [&](size_t v) {
    for (int k = start[v] + 1; k < start[v + 1]; ++k)
      for (int m = k; m > start[v] && rows[m - 1] > rows[m]; --m) {
        std::swap(rows[m - 1], rows[m]);
        std::swap(values[m - 1], values[m]);
      }
  });
  // An intrinsic triangulation may join two vertices by two edges, or a vertex to itself: their
  // entries are summed into one, as a sum over edges would.
  int kept = 0;
  for (int v = 0; v < vertex_count; ++v) {
    const int begin = start[size_t(v)], end = start[size_t(v) + 1];
    start[size_t(v)] = kept;
    for (int k = begin; k < end; ++k) {
      if (kept > start[size_t(v)] && rows[kept - 1] == rows[k]) {
        values[kept - 1] += values[k];
        continue;
      }
      rows[kept] = rows[k];
      values[kept++] = values[k];
    }
  }
  start[size_t(vertex_count)] = kept;
  std::copy(start.begin(), start.end(), laplacian.outerIndexPtr());
  laplacian.data().resize(kept);
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
