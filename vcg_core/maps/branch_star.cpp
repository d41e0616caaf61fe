#include "maps/branch_star.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <set>
#include <utility>

#include "common/stack_pool.h"
#include "maps/floater_embedding.h"
#include "mesh/local_numbers.h"

namespace meromorph {

std::vector<int> ordered_ring(const FaceIncidence &in, int vertex) {
  std::vector<std::pair<int, int>> next; // (a, b) for each face (vertex, a, b)
  for (int f : in.faces_of_vertex[size_t(vertex)]) {
    const auto &corners = in.corners[size_t(f)];
    const int k = int(std::find(corners.begin(), corners.end(), vertex) - corners.begin());
    next.push_back({corners[size_t((k + 1) % 3)], corners[size_t((k + 2) % 3)]});
  }
  if (next.empty()) return {};
  std::vector<int> ring{next.front().first};
  while (ring.size() <= next.size()) {
    auto step = std::find_if(next.begin(), next.end(),
                             [&](const std::pair<int, int> &n) { return n.first == ring.back(); });
    if (step == next.end()) return {};
    if (step->second == ring.front()) break;
    ring.push_back(step->second);
  }
  return ring.size() == next.size() ? ring : std::vector<int>{};
}

namespace {

// The vertices `distance` lists, numbered in its order (by vertex), found in constant time (their
// chart positions are kept in that numbering), and their ring distances.
struct RegionVertices {};
class RegionIndex {
public:
  RegionIndex(const RingDistances &distance, size_t vertex_count)
      : distance_(distance), numbers_(vertices_of(distance), vertex_count) {}
  // The vertex's number, -1 beyond the region.
  int operator()(int vertex) const { return numbers_(vertex); }
  // Its ring distance, -1 beyond the region.
  int ring(int vertex) const {
    const int number = numbers_(vertex);
    return number < 0 ? -1 : distance_.begin()[number].second;
  }

private:
  static std::vector<int> vertices_of(const RingDistances &distance) {
    std::vector<int> vertices;
    for (const auto &entry : distance)
      vertices.push_back(entry.first);
    return vertices;
  }
  const RingDistances &distance_;
  LocalNumbers<RegionVertices> numbers_;
};

// Chart positions by region number.
using ChartPositions = std::vector<Eigen::Vector2d>;

// The angle from a to b about the chart's origin, in (-pi, pi].
double turn(const Eigen::Vector2d &a, const Eigen::Vector2d &b) {
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}

// Square roots of the chart positions along a closed loop that turns twice around the origin,
// continuous along it (the first one's root taken at half its angle in (-pi, pi]); false if the
// loop does not turn twice.
bool roots_along(const std::vector<int> &loop, const RegionIndex &index,
                 const ChartPositions &chart, PlanePositions &root) {
  auto at = [&](int v) -> const Eigen::Vector2d & { return chart[size_t(index(v))]; };
  double angle = std::atan2(at(loop[0]).y(), at(loop[0]).x());
  const double start = angle;
  for (size_t k = 0; k < loop.size(); ++k) {
    if (k > 0) angle += turn(at(loop[k - 1]), at(loop[k]));
    const double radius = std::sqrt(at(loop[k]).norm());
    root[loop[k]] = radius * Eigen::Vector2d(std::cos(angle / 2), std::sin(angle / 2));
  }
  angle += turn(at(loop.back()), at(loop.front()));
  return std::abs(angle - start - 4 * M_PI) < 1;
}

// Whether the roots of `outer` are on the sheet that continues the one-ring's (from `start`, a
// one-ring vertex whose root is set) along a shortest path out; if not, they are turned over.
// False where no path leads out.
bool same_sheet(const FaceIncidence &in, const RegionIndex &index, int rings, int start,
                const ChartPositions &chart, const std::vector<int> &outer, PlanePositions &root) {
  std::vector<int> path{start};
  while (index.ring(path.back()) < rings + 1) {
    // One ring further out; the last step onto the outer loop (whose roots are set).
    const int next = index.ring(path.back()) + 1;
    int step = -1;
    for (int f : in.faces_of_vertex[size_t(path.back())])
      for (int w : in.corners[size_t(f)])
        if (index.ring(w) == next && (next <= rings || root.count(w))) step = w;
    if (step < 0) return false;
    path.push_back(step);
  }
  double angle = std::atan2(root.at(start).y(), root.at(start).x()) * 2;
  for (size_t k = 1; k < path.size(); ++k)
    angle += turn(chart[size_t(index(path[k - 1]))], chart[size_t(index(path[k]))]);
  const Eigen::Vector2d along(std::cos(angle / 2), std::sin(angle / 2));
  if (root.at(path.back()).dot(along) < 0)
    for (int v : outer)
      root[v] = -root[v];
  return true;
}

// Vertex v's root (of its chart position) nearer to the root of a neighbour that has one; false
// where none has.
bool root_beside(const FaceIncidence &in, const RegionIndex &index, const ChartPositions &chart,
                 int v, PlanePositions &root) {
  for (int f : in.faces_of_vertex[size_t(v)])
    for (int w : in.corners[size_t(f)]) {
      const auto beside = root.find(w);
      if (w == v || beside == root.end()) continue;
      const Eigen::Vector2d &x = chart[size_t(index(v))];
      const double angle = std::atan2(x.y(), x.x()) / 2;
      const Eigen::Vector2d r =
          std::sqrt(x.norm()) * Eigen::Vector2d(std::cos(angle), std::sin(angle));
      root[v] = r.dot(beside->second) >= 0 ? r : Eigen::Vector2d(-r);
      return true;
    }
  return false;
}

} // namespace

std::optional<std::vector<std::pair<int, Eigen::Vector3d>>>
reembed_around_branch(const Mesh &mesh, const FaceIncidence &in,
                      const std::vector<Eigen::Vector3d> &sphere, int branch, int rings,
                      OneRing one_ring) {
  const bool ring_kept = one_ring == OneRing::kept;
  const std::vector<int> ring = ring_kept ? ordered_ring(in, branch) : std::vector<int>{};
  if (ring_kept ? ring.empty() || rings < 2 : rings < 1) return std::nullopt;
  const RingDistances distance = ring_distances(in, {branch}, rings + 1);
  const RegionIndex index(distance, in.faces_of_vertex.size());
  const GnomonicChart gnomonic(sphere[size_t(branch)]);
  ChartPositions chart(distance.size(), Eigen::Vector2d::Zero());
  for (const auto &[v, d] : distance)
    if (v != branch && !gnomonic.to_chart(sphere[size_t(v)], chart[size_t(index(v))]))
      return std::nullopt;
  // The outer ring in order: the boundary of the faces within `rings` rings, chained. Both ends
  // of a boundary side are rings + 1 away (the face beyond it has no nearer corner), and so are
  // those of its reverse: the faces' sides between such vertices are all the chaining reads.
  auto outermost = [&](int v) { return index.ring(v) == rings + 1; };
  std::vector<std::pair<int, int>> outer_sides;
  for (const auto &[v, d] : distance)
    if (d <= rings)
      for (int f : in.faces_of_vertex[size_t(v)]) {
        const auto &t = in.corners[size_t(f)];
        for (int k = 0; k < 3; ++k)
          if (outermost(t[size_t(k)]) && outermost(t[size_t((k + 1) % 3)]))
            outer_sides.push_back({t[size_t(k)], t[size_t((k + 1) % 3)]});
      }
  const BoundaryLoops boundary = chain_boundary(std::move(outer_sides));
  if (boundary.loops.size() != 1) return std::nullopt; // not one loop
  const std::vector<int> &outer = boundary.loops.front();
  StackPool pool; // (the roots' nodes: common/stack_pool.h)
  PlanePositions root(&pool);
  if (!roots_along(outer, index, chart, root)) return std::nullopt;
  const int first_free = ring_kept ? 2 : 1;
  if (ring_kept && !roots_along(ring, index, chart, root)) return std::nullopt;
  // The two loops' roots on the same sheet of the square root: along a shortest path from the
  // one-ring out, the image turns little per edge, so the root continues without a jump. (A
  // moving one-ring leaves the outer loop's sheet free: both square to the same.)
  if (ring_kept && !same_sheet(in, index, rings, ring[0], chart, outer, root)) return std::nullopt;
  // The outermost vertices off the loop (touching the region at a vertex or an edge only) keep
  // their values too: their roots on the sheet of a neighbour's.
  for (bool placed_one = true; placed_one;) {
    placed_one = false;
    for (const auto &[v, d] : distance)
      if (d == rings + 1 && !root.count(v)) placed_one |= root_beside(in, index, chart, v, root);
  }
  std::vector<int> free;
  for (const auto &[v, d] : distance)
    if (d >= first_free && d <= rings) {
      free.push_back(v);
      root[v] = Eigen::Vector2d::Zero();
    }
  if (!ring_kept) root[branch] = Eigen::Vector2d::Zero(); // the branch value, the chart's centre
  if (free.empty() || !floater_embedding(mesh, in, free, root)) return std::nullopt;
  std::vector<std::pair<int, Eigen::Vector3d>> placed;
  for (int v : free) {
    const Eigen::Vector2d &r = root[v];
    placed.push_back(
        {v, gnomonic.to_sphere(Eigen::Vector2d(r.x() * r.x() - r.y() * r.y(), 2 * r.x() * r.y()))});
  }
  return placed;
}

} // namespace meromorph
