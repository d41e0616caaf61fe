#include "genus1_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "errors.h"
#include "face_vectors.h"
#include "genus1_branch_placement.h"

namespace meromorph {

Genus1Map genus1_map(const Mesh &mesh, const MeshEdges &edges, const Eigen::VectorXcd &psi,
                     Complex period_a, Complex period_b, int origin_vertex) {
  const int vertex_count = int(mesh.vert.size());
  // The double pole doubles the corners at the origin: they must be well below 90 degrees. And
  // the pole's neighbourhood covers a large part of the sphere: it goes where the flat metric is
  // largest (on a long thin part, whose flat image is exponentially small, the rest of the
  // surface would crowd into a spot that doubles do not resolve).
  if (origin_vertex < 0) {
    const std::vector<double> widest = widest_flat_corners(mesh, edges, psi);
    const std::vector<double> scale = flat_area_ratios(mesh, edges, psi);
    origin_vertex = int(std::min_element(widest.begin(), widest.end()) - widest.begin());
    double best_scale = -1;
    for (int v = 0; v < vertex_count; ++v)
      if (widest[size_t(v)] < 80 * M_PI / 180 && scale[size_t(v)] > best_scale) {
        best_scale = scale[size_t(v)];
        origin_vertex = v;
      }
  }
  if (origin_vertex >= vertex_count)
    throw ArgumentError("origin vertex " + std::to_string(origin_vertex) + " does not exist (0.." +
                        std::to_string(vertex_count - 1) + ")");
  Genus1Map out{{}, {}, WeierstrassP(period_a, period_b), {}, -1};

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
  const auto roots = out.p_function.roots();
  for (int k = 0; k < 3; ++k)
    out.branch_values[k] = {roots[k], false};

  out.origin_vertex = origin_vertex;
  out.branch_values[3] = {Complex(), true};
  return out;
}

} // namespace meromorph
