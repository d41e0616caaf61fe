#include "maps/genus1_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>

#include "common/errors.h"
#include "common/parallel_for.h"
#include "maps/genus1_branch_placement.h"
#include "mesh/face_vectors.h"

namespace meromorph {

namespace {

// The automatic origin. The double pole doubles the corners there: they must be well below 90
// degrees. The pole's neighbourhood covers a large part of the sphere: it goes where the flat
// metric is large (on a long thin part, whose flat image is exponentially small, the rest of the
// surface would crowd into a spot that doubles do not resolve). And the three half periods from
// it, where P branches too, must fall near vertices with narrow corners. Of the vertices where
// the flat metric is at least half its 90th percentile, the 8 whose widest corner is narrowest
// are candidates, ordered by their worst spot (themselves, or the best of the 8 vertices nearest
// each half period): the narrower its widest corner, the better.
// An angle (radians) rounded to 1e-9: on symmetric meshes many vertices tie, and ties are broken
// by vertex index, not by rounding noise (which a scale of the input or a summation order moves).
// A NaN (a degenerate flat corner) counts as the widest: sorts need a strict weak order.
double settled(double angle) {
  return std::isnan(angle) ? std::numeric_limits<double>::infinity() : std::round(angle * 1e9);
}

std::vector<int> origin_candidates(const PreparedMesh &prepared, const Eigen::VectorXcd &psi,
                                   const std::vector<Complex> &flat,
                                   const WeierstrassP &p_function) {
  const size_t vertex_count = prepared.mesh.vert.size();
  const std::vector<double> widest = widest_flat_corners(prepared, psi);
  const std::vector<double> scale = flat_area_ratios(prepared, psi);
  std::vector<double> sorted = scale;
  for (double &ratio : sorted) // NaN (degenerate faces) would break nth_element's order
    if (std::isnan(ratio)) ratio = 0;
  const auto high = sorted.begin() + std::ptrdiff_t(0.9 * double(vertex_count - 1));
  std::nth_element(sorted.begin(), high, sorted.end());
  const double enough = 0.5 * *high;
  std::vector<int> candidates;
  for (size_t v = 0; v < vertex_count; ++v)
    if (scale[v] >= enough) candidates.push_back(int(v));
  if (candidates.empty()) // no finite area ratio reaches the bar (needles): every vertex competes
    for (size_t v = 0; v < vertex_count; ++v)
      candidates.push_back(int(v));
  const size_t kept = std::min<size_t>(8, candidates.size());
  std::partial_sort(candidates.begin(), candidates.begin() + std::ptrdiff_t(kept), candidates.end(),
                    [&](int a, int b) {
                      return std::make_pair(settled(widest[size_t(a)]), a) <
                             std::make_pair(settled(widest[size_t(b)]), b);
                    });
  candidates.resize(kept);
  // Flat positions in lattice coordinates (z = (a + b tau) w1), for the distances below.
  const Complex tau = p_function.tau(), w1 = 2.0 * p_function.half_periods()[0];
  auto lattice_coordinates = [&](const Complex &z) {
    const Complex u = z / w1;
    const double b = u.imag() / tau.imag();
    return std::array<double, 2>{u.real() - b * tau.real(), b};
  };
  std::vector<std::array<double, 2>> lattice(vertex_count);
  parallel_for(vertex_count, [&](size_t v) { lattice[v] = lattice_coordinates(flat[v]); });
  std::vector<std::pair<double, int>> scored;
  for (int origin : candidates) {
    double score = widest[size_t(origin)];
    for (const Complex &half : p_function.half_periods()) {
      const std::array<double, 2> target = lattice_coordinates(flat[size_t(origin)] + half);
      // Squared distances: only their order counts.
      const auto nearest = parallel_smallest(vertex_count, 8, [&](size_t v) {
        const double da = lattice[v][0] - target[0], db = lattice[v][1] - target[1];
        return std::norm(da - std::round(da) + (db - std::round(db)) * tau);
      });
      double spot = std::numeric_limits<double>::infinity();
      for (const auto &[distance, v] : nearest)
        spot = std::min(spot, widest[size_t(v)]);
      score = std::max(score, spot);
    }
    scored.push_back({settled(score), origin});
  }
  std::sort(scored.begin(), scored.end());
  std::vector<int> ordered;
  for (const auto &[score, origin] : scored)
    ordered.push_back(origin);
  return ordered;
}

} // namespace

std::vector<int> genus1_origin_candidates(const PreparedMesh &prepared, const Eigen::VectorXcd &psi,
                                          const WeierstrassP &p_function) {
  return origin_candidates(
      prepared, psi, integrated_form(0, prepared.edges_at_vertex, prepared.edges, psi), p_function);
}

Genus1Map genus1_map(const PreparedMesh &prepared, const Eigen::VectorXcd &psi, Complex period_a,
                     Complex period_b, int origin_vertex) {
  const int vertex_count = int(prepared.mesh.vert.size());
  const MeshEdges &edges = prepared.edges;
  if (origin_vertex >= vertex_count)
    throw ArgumentError("origin vertex " + std::to_string(origin_vertex) + " does not exist (0.." +
                        std::to_string(vertex_count - 1) + ")");
  Genus1Map out{{}, {}, WeierstrassP(period_a, period_b), {}, -1};
  const IndexLists &incident = prepared.edges_at_vertex;
  if (origin_vertex < 0)
    origin_vertex =
        origin_candidates(prepared, psi, integrated_form(0, incident, edges, psi), out.p_function)
            .front();
  out.flat = integrated_form(origin_vertex, incident, edges, psi);

  out.values.resize(size_t(vertex_count));
  parallel_for(out.flat.size(), [&](size_t v) {
    const bool pole = out.p_function.is_lattice_point(out.flat[v], 1e-12);
    out.values[v] = PlaneValue{pole ? Complex() : out.p_function.value(out.flat[v]), pole};
  });
  const auto roots = out.p_function.roots();
  for (int k = 0; k < 3; ++k)
    out.branch_values[k] = {roots[k], false};

  out.origin_vertex = origin_vertex;
  out.branch_values[3] = {Complex(), true};
  return out;
}

std::vector<Complex> integrated_form(int root, const IndexLists &incident, const MeshEdges &edges,
                                     const Eigen::VectorXcd &psi) {
  std::vector<Complex> flat(incident.size(), Complex(0, 0));
  std::vector<char> reached(incident.size(), 0);
  std::queue<int> frontier;
  frontier.push(root);
  reached[size_t(root)] = 1;
  while (!frontier.empty()) {
    const int v = frontier.front();
    frontier.pop();
    for (int e : incident[size_t(v)]) {
      const bool forward = edges.vertices[e][0] == v;
      const int w = forward ? edges.vertices[e][1] : edges.vertices[e][0];
      if (reached[size_t(w)]) continue;
      reached[size_t(w)] = 1;
      flat[size_t(w)] = flat[size_t(v)] + (forward ? psi[e] : -psi[e]);
      frontier.push(w);
    }
  }
  return flat;
}

} // namespace meromorph
