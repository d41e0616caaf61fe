#include "remesh/geodesic_sphere.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <Eigen/Geometry>

namespace meromorph {
namespace {

struct Icosahedron {
  std::array<Eigen::Vector3d, 12> vertices;
  std::array<std::array<int, 3>, 20> faces;
};

Icosahedron icosahedron() {
  const double t = (1 + std::sqrt(5.0)) / 2;
  Icosahedron out;
  const double raw[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                             {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                             {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (int v = 0; v < 12; ++v)
    out.vertices[v] = Eigen::Vector3d(raw[v][0], raw[v][1], raw[v][2]).normalized();
  out.faces = {{{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}}};
  for (auto &face : out.faces) { // counter-clockwise seen from outside
    const Eigen::Vector3d &a = out.vertices[face[0]], &b = out.vertices[face[1]],
                          &c = out.vertices[face[2]];
    if ((b - a).cross(c - a).dot(a) < 0) std::swap(face[1], face[2]);
  }
  return out;
}

// Vertex numbering of the subdivided icosahedron: corners, then the k - 1 inner points of each
// edge (from its lower-numbered end), then the inner points of each face.
class GridNumbering {
public:
  GridNumbering(const Icosahedron &base, int k, GeodesicSphere &out)
      : base_(base), k_(k), out_(out) {
    for (const Eigen::Vector3d &corner : base.vertices)
      out.vertices.push_back(corner);
  }

  // Point (i, j) of face f: corner 0 + i/k (corner 1 - corner 0) + j/k (corner 2 - corner 0).
  int vertex(int f, int i, int j) {
    const auto &c = base_.faces[f];
    if (i == 0 && j == 0) return c[0];
    if (i == k_ && j == 0) return c[1];
    if (i == 0 && j == k_) return c[2];
    if (j == 0) return edge_point(c[0], c[1], i);
    if (i == 0) return edge_point(c[0], c[2], j);
    if (i + j == k_) return edge_point(c[1], c[2], j);
    auto [slot, added] = face_points_.try_emplace({f, i, j}, int(out_.vertices.size()));
    if (added) {
      const Eigen::Vector3d &a = base_.vertices[c[0]], &b = base_.vertices[c[1]],
                            &d = base_.vertices[c[2]];
      out_.vertices.push_back((a + (b - a) * i / k_ + (d - a) * j / k_).normalized());
    }
    return slot->second;
  }

private:
  int edge_point(int from, int to, int step) {
    if (from > to) {
      std::swap(from, to);
      step = k_ - step;
    }
    auto [slot, added] = edge_points_.try_emplace({from, to, step}, int(out_.vertices.size()));
    if (added) {
      const Eigen::Vector3d &a = base_.vertices[from], &b = base_.vertices[to];
      out_.vertices.push_back((a + (b - a) * step / k_).normalized());
    }
    return slot->second;
  }

  const Icosahedron &base_;
  int k_;
  GeodesicSphere &out_;
  std::map<std::array<int, 3>, int> edge_points_, face_points_;
};

bool holds(const GeodesicSphere &sphere, const std::array<int, 3> &face, const Eigen::Vector3d &p) {
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d &a = sphere.vertices[face[k]], &b = sphere.vertices[face[(k + 1) % 3]];
    if (a.cross(b).dot(p) < 0) return false;
  }
  return sphere.vertices[face[0]].dot(p) > 0;
}

using SphereSide = std::pair<int, int>;

SphereSide sphere_side(int a, int b) {
  return std::make_pair(std::min(a, b), std::max(a, b));
}

double longest_side(const GeodesicSphere &sphere, const std::array<int, 3> &face) {
  double longest = 0;
  for (int k = 0; k < 3; ++k)
    longest =
        std::max(longest, (sphere.vertices[face[k]] - sphere.vertices[face[(k + 1) % 3]]).norm());
  return longest;
}

// The points to refine around, each with the side length to refine down to: the branch values
// closer to another than an edge of the sphere and than 0.05 (a third of their separation), and
// the points of `refine_at` (an eighth of the longest side).
std::vector<std::pair<Eigen::Vector3d, double>>
points_to_refine_around(const GeodesicSphere &sphere, const std::vector<Eigen::Vector3d> &values,
                        const std::vector<Eigen::Vector3d> &refine_at) {
  double edge = 0;
  for (const auto &face : sphere.faces)
    edge = std::max(edge, (sphere.vertices[face[0]] - sphere.vertices[face[1]]).norm());
  std::vector<std::pair<Eigen::Vector3d, double>> close;
  for (size_t a = 0; a < values.size(); ++a) {
    double separation = 1e300;
    for (size_t b = 0; b < values.size(); ++b)
      if (b != a) separation = std::min(separation, (values[a] - values[b]).norm());
    if (separation < std::min(edge, 0.05))
      close.push_back({values[a], std::max(separation / 3, 1e-9)});
  }
  for (const Eigen::Vector3d &point : refine_at)
    close.push_back({point.normalized(), edge / 8});
  return close;
}

// The sides to split: those of the faces marked, and, closing the marking, those of every face
// with two or three sides split (which is split in four too). Each side's midpoint is -1.
std::map<SphereSide, int> sides_to_split(const GeodesicSphere &sphere, std::vector<char> &split) {
  std::map<SphereSide, int> middle_of;
  for (size_t f = 0; f < sphere.faces.size(); ++f)
    if (split[f])
      for (int k = 0; k < 3; ++k)
        middle_of.emplace(sphere_side(sphere.faces[f][k], sphere.faces[f][(k + 1) % 3]), -1);
  for (bool grew = true; grew;) {
    grew = false;
    for (size_t f = 0; f < sphere.faces.size(); ++f) {
      const auto &face = sphere.faces[f];
      if (split[f]) continue;
      int sides = 0;
      for (int k = 0; k < 3; ++k)
        sides += middle_of.count(sphere_side(face[k], face[(k + 1) % 3]));
      if (sides < 2) continue;
      split[f] = grew = true;
      for (int k = 0; k < 3; ++k)
        middle_of.emplace(sphere_side(face[k], face[(k + 1) % 3]), -1);
    }
  }
  return middle_of;
}

// The sides split at their midpoints (pushed onto the sphere): a face with three split is split
// 1-to-4, one with one is halved across it; `touched` marks the new vertices and the corners of
// the faces that changed.
void split_sides(GeodesicSphere &sphere, std::map<SphereSide, int> &middle_of,
                 std::vector<char> &touched) {
  for (auto &[ends, middle] : middle_of) {
    middle = int(sphere.vertices.size());
    sphere.vertices.push_back(
        (sphere.vertices[ends.first] + sphere.vertices[ends.second]).normalized());
    touched.push_back(1);
  }
  const size_t count = sphere.faces.size();
  for (size_t f = 0; f < count; ++f) {
    const std::array<int, 3> face = sphere.faces[f];
    std::array<int, 3> m{};
    int sides = 0, which = 0;
    for (int k = 0; k < 3; ++k) {
      const auto found = middle_of.find(sphere_side(face[k], face[(k + 1) % 3]));
      m[k] = found == middle_of.end() ? -1 : found->second;
      if (m[k] >= 0) ++sides, which = k;
    }
    if (sides == 3) {
      sphere.faces[f] = {face[0], m[0], m[2]};
      sphere.faces.push_back({m[0], face[1], m[1]});
      sphere.faces.push_back({m[2], m[1], face[2]});
      sphere.faces.push_back({m[0], m[1], m[2]});
    } else if (sides == 1) { // halved across the split side
      const int a = face[which], b = face[(which + 1) % 3], c = face[(which + 2) % 3];
      sphere.faces[f] = {a, m[which], c};
      sphere.faces.push_back({m[which], b, c});
    }
    if (sides > 0)
      for (int corner : face)
        touched[size_t(corner)] = 1;
  }
}

// Sphere faces refined around branch values that lie close to another one (closer than an edge
// of the sphere and than 0.05): each round, a face whose centre lies within 0.6 of its longest side
// from such a value (the faces at the value) is split 1-to-4 (the midpoints pushed onto the
// sphere) while that side is longer than a third of the value's distance to the other; a
// neighbour with one side split is halved, one with more is split too. The sphere mesh grades
// down to the pair in a few faces per halving, so each value gets a vertex of its own nearby
// instead of slivers between two values a hair apart. Points in `refine_at` get the same, down
// to an eighth of the longest side. Returns, per vertex, whether refinement
// made or changed faces around it.
std::vector<char> refine_around_close_values(GeodesicSphere &sphere,
                                             const std::vector<Eigen::Vector3d> &values,
                                             const std::vector<Eigen::Vector3d> &refine_at) {
  std::vector<char> touched(sphere.vertices.size(), 0);
  const auto close = points_to_refine_around(sphere, values, refine_at);
  if (close.empty()) return touched;
  for (int round = 0; round < 40; ++round) {
    std::vector<char> split(sphere.faces.size(), 0);
    bool any = false;
    for (size_t f = 0; f < sphere.faces.size(); ++f) {
      const auto &face = sphere.faces[f];
      const Eigen::Vector3d middle =
          (sphere.vertices[face[0]] + sphere.vertices[face[1]] + sphere.vertices[face[2]]) / 3;
      const double longest = longest_side(sphere, face);
      for (const auto &[value, third] : close)
        if (longest > third && (middle - value).norm() < 0.6 * longest) split[f] = any = true;
    }
    if (!any) break;
    std::map<SphereSide, int> middle_of = sides_to_split(sphere, split);
    split_sides(sphere, middle_of, touched);
  }
  return touched;
}

// Edge flips toward the Delaunay triangulation of the sphere (the convex hull of its points) on
// the sides with an end in `touched`: a side is flipped when the far corner of the face across it
// lies inside the circumcircle of the face (beyond the plane through its corners). A flip that
// would join two branch values, or turn a face over, is not made.
void flip_touched_toward_delaunay(GeodesicSphere &sphere, const std::vector<char> &touched) {
  for (int round = 0; round < 20; ++round) {
    std::map<std::pair<int, int>, std::pair<int, int>> across; // directed side -> face, corner
    for (size_t f = 0; f < sphere.faces.size(); ++f)
      for (int k = 0; k < 3; ++k)
        across[{sphere.faces[f][k], sphere.faces[f][(k + 1) % 3]}] = {int(f), (k + 2) % 3};
    bool flipped = false;
    std::vector<char> changed(sphere.faces.size(), 0);
    for (size_t f = 0; f < sphere.faces.size(); ++f)
      for (int k = 0; k < 3 && !changed[f]; ++k) {
        const int a = sphere.faces[f][k], b = sphere.faces[f][(k + 1) % 3],
                  c = sphere.faces[f][(k + 2) % 3];
        if (!touched[size_t(a)] && !touched[size_t(b)]) continue;
        const auto other = across.find({b, a});
        if (other == across.end() || changed[size_t(other->second.first)]) continue;
        const int g = other->second.first,
                  d = sphere.faces[size_t(g)][size_t(other->second.second)];
        const Eigen::Vector3d &pa = sphere.vertices[a], &pb = sphere.vertices[b],
                              &pc = sphere.vertices[c], &pd = sphere.vertices[d];
        const Eigen::Vector3d normal = (pb - pa).cross(pc - pa);
        if (!(normal.dot(pd - pa) > 1e-12 * normal.norm() * (pd - pa).norm())) continue;
        if (sphere.branch_value[c] >= 0 && sphere.branch_value[d] >= 0) continue;
        if (across.count({c, d}) || across.count({d, c})) continue; // c and d already joined
        // The new faces (c, a, d) and (d, b, c) must stay counter-clockwise seen from outside.
        if ((pa - pc).cross(pd - pc).dot(pc) <= 0 || (pb - pd).cross(pc - pd).dot(pd) <= 0)
          continue;
        sphere.faces[f] = {c, a, d};
        sphere.faces[size_t(g)] = {d, b, c};
        changed[f] = changed[size_t(g)] = 1;
        flipped = true;
      }
    if (!flipped) break;
  }
}

// Branch value `value` (index `index`) onto a vertex: the nearest, or a new one splitting its face;
// returns that vertex.
int put_on_vertex(GeodesicSphere &sphere, const Eigen::Vector3d &value, int index) {
  int nearest = 0;
  for (int v = 1; v < int(sphere.vertices.size()); ++v)
    if ((sphere.vertices[v] - value).squaredNorm() <
        (sphere.vertices[nearest] - value).squaredNorm())
      nearest = v;
  if (sphere.branch_value[nearest] < 0) {
    sphere.vertices[nearest] = value;
    sphere.branch_value[nearest] = index;
    return nearest;
  }
  for (size_t f = 0; f < sphere.faces.size(); ++f) {
    const std::array<int, 3> face = sphere.faces[f];
    if (!holds(sphere, face, value)) continue;
    const int added = int(sphere.vertices.size());
    sphere.vertices.push_back(value);
    sphere.branch_value.push_back(index);
    sphere.faces[f] = {face[0], face[1], added};
    sphere.faces.push_back({face[1], face[2], added});
    sphere.faces.push_back({face[2], face[0], added});
    return added;
  }
  return -1;
}

// Splits at its midpoint every edge whose two ends carry branch values: the lift of such an arc
// is not one edge but d - (e - 1) paths between the two branch vertices, which one edge of the
// remesh cannot stand for.
void split_edges_between_branch_values(GeodesicSphere &sphere) {
  for (bool split = true; split;) {
    split = false;
    for (size_t f = 0; f < sphere.faces.size() && !split; ++f)
      for (int k = 0; k < 3 && !split; ++k) {
        const int a = sphere.faces[f][k], b = sphere.faces[f][(k + 1) % 3];
        if (sphere.branch_value[a] < 0 || sphere.branch_value[b] < 0) continue;
        const int middle = int(sphere.vertices.size());
        sphere.vertices.push_back((sphere.vertices[a] + sphere.vertices[b]).normalized());
        sphere.branch_value.push_back(-1);
        const size_t count = sphere.faces.size();
        for (size_t g = 0; g < count; ++g)
          for (int m = 0; m < 3; ++m) {
            const std::array<int, 3> face = sphere.faces[g];
            const int from = face[m], to = face[(m + 1) % 3], other = face[(m + 2) % 3];
            if (!((from == a && to == b) || (from == b && to == a))) continue;
            sphere.faces[g] = {from, middle, other};
            sphere.faces.push_back({middle, to, other});
            break;
          }
        split = true;
      }
  }
}

} // namespace

GeodesicSphere geodesic_sphere(int frequency, const std::vector<Eigen::Vector3d> &branch_values,
                               const std::vector<Eigen::Vector3d> &refine_at) {
  GeodesicSphere out;
  out.frequency = std::max(1, frequency);
  const int k = out.frequency;
  const Icosahedron base = icosahedron();
  GridNumbering numbering(base, k, out);
  for (int f = 0; f < 20; ++f)
    for (int i = 0; i < k; ++i)
      for (int j = 0; i + j < k; ++j) {
        const int a = numbering.vertex(f, i, j), b = numbering.vertex(f, i + 1, j),
                  c = numbering.vertex(f, i, j + 1);
        out.faces.push_back({a, b, c});
        if (i + j + 2 <= k) out.faces.push_back({b, numbering.vertex(f, i + 1, j + 1), c});
      }
  out.branch_value.assign(out.vertices.size(), -1);
  std::vector<Eigen::Vector3d> distinct;
  for (const Eigen::Vector3d &value : branch_values) {
    bool seen = false;
    for (const Eigen::Vector3d &other : distinct)
      seen |= (other - value).norm() < 1e-12;
    if (!seen) distinct.push_back(value.normalized());
  }
  std::vector<char> touched = refine_around_close_values(out, distinct, refine_at);
  out.branch_value.assign(out.vertices.size(), -1);
  for (size_t b = 0; b < distinct.size(); ++b) {
    const int vertex = put_on_vertex(out, distinct[b], int(b));
    touched.resize(out.vertices.size(), 0);
    if (vertex >= 0) touched[size_t(vertex)] = 1;
  }
  flip_touched_toward_delaunay(out, touched);
  split_edges_between_branch_values(out);
  out.neighbours.assign(out.vertices.size(), {});
  for (const auto &face : out.faces)
    for (int c = 0; c < 3; ++c) {
      auto &around = out.neighbours[face[c]];
      for (int other : {face[(c + 1) % 3], face[(c + 2) % 3]})
        if (std::find(around.begin(), around.end(), other) == around.end()) around.push_back(other);
    }
  return out;
}

int frequency_for_vertices(long long vertices, int sheets, int ramification) {
  const double per_sheet = (double(vertices) + ramification) / std::max(sheets, 1);
  return std::max(1, int(std::lround(std::sqrt(std::max(0.0, per_sheet - 2) / 10))));
}

} // namespace meromorph
