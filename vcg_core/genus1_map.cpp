#include "genus1_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "errors.h"
#include "face_vectors.h"

namespace meromorph {

Genus1Map genus1_map(const Mesh &mesh, const MeshEdges &edges, const Eigen::VectorXcd &psi,
                     Complex period_a, Complex period_b, int origin_vertex) {
  const int vertex_count = int(mesh.vert.size());
  // At a branch vertex of local degree 2 the map doubles angles: a corner of 90 degrees or more
  // there flattens or folds its face. Branch vertices are chosen among those whose corners are
  // acute.
  std::vector<double> widest_corner(vertex_count, 0.0);
  for (const MeshFace &face : mesh.face)
    for (int k = 0; k < 3; ++k) {
      const int v = index_of(mesh, face.cV(k));
      widest_corner[v] = std::max(widest_corner[v], corner_angle(face, k));
    }
  auto acute = [&](int v) { return widest_corner[v] < M_PI / 2 - 1e-9; };
  if (origin_vertex < 0) {
    origin_vertex = 0;
    for (int v = 0; v < vertex_count; ++v)
      if (acute(v)) {
        origin_vertex = v;
        break;
      }
  }
  if (origin_vertex >= vertex_count)
    throw ArgumentError("origin vertex " + std::to_string(origin_vertex) + " does not exist (0.." +
                        std::to_string(vertex_count - 1) + ")");
  Genus1Map out{{}, {}, WeierstrassP(period_a, period_b), {}, {}, {}, -1};

  const std::vector<std::vector<int>> incident = edges_at_vertices(edges, vertex_count);
  out.flat.assign(vertex_count, Complex(0, 0));
  std::vector<char> reached(vertex_count, 0);
  std::queue<int> frontier;
  frontier.push(origin_vertex);
  reached[origin_vertex] = 1;
  while (!frontier.empty()) {
    const int v = frontier.front();
    frontier.pop();
    for (int e : incident[v]) {
      const bool forward = edges.vertices[e][0] == v;
      const int w = forward ? edges.vertices[e][1] : edges.vertices[e][0];
      if (reached[w]) continue;
      reached[w] = 1;
      out.flat[w] = out.flat[v] + (forward ? psi[e] : -psi[e]);
      frontier.push(w);
    }
  }

  out.values.reserve(vertex_count);
  for (const Complex &z : out.flat) {
    const bool pole = out.p_function.is_lattice_point(z, 1e-12);
    out.values.push_back(PlaneValue{pole ? Complex() : out.p_function.value(z), pole});
  }
  out.side_midpoints.resize(3 * mesh.face.size());
  for (size_t f = 0; f < mesh.face.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      // The side from corner k+1 to corner k+2 is face side k+1 (sides join corners j and j+1).
      const int side = (k + 1) % 3;
      const int from = index_of(mesh, mesh.face[f].cV(side));
      const int e = edges.face_edges[f][side];
      const Complex z = out.flat[from] + 0.5 * double(edges.face_signs[f][side]) * psi[e];
      const bool pole = out.p_function.is_lattice_point(z, 1e-12);
      out.side_midpoints[3 * f + size_t(k)] = {pole ? Complex() : out.p_function.value(z), pole};
    }
  const auto roots = out.p_function.roots();
  for (int k = 0; k < 3; ++k)
    out.branch_values[k] = {roots[k], false};

  // The critical points of P are the half periods: the vertex nearest each one (modulo the
  // lattice) takes the critical value, so the map branches at that vertex (branch_snapping.h).
  const auto half_periods = out.p_function.half_periods();
  for (int k = 0; k < 3; ++k) {
    std::vector<std::pair<double, int>> by_distance;
    for (int v = 0; v < vertex_count; ++v)
      by_distance.push_back({out.p_function.lattice_distance(out.flat[v] - half_periods[k]), v});
    const size_t count = std::min<size_t>(12, by_distance.size());
    std::partial_sort(by_distance.begin(), by_distance.begin() + long(count), by_distance.end());
    for (size_t i = 0; i < count; ++i)
      out.branch_candidates[k].push_back(by_distance[i].second);
  }
  out.origin_vertex = origin_vertex;
  out.branch_values[3] = {Complex(), true};
  return out;
}

} // namespace meromorph
