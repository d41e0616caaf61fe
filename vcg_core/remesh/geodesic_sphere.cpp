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

// Branch value `value` (index `index`) onto a vertex: the nearest, or a new one splitting its face.
void put_on_vertex(GeodesicSphere &sphere, const Eigen::Vector3d &value, int index) {
  int nearest = 0;
  for (int v = 1; v < int(sphere.vertices.size()); ++v)
    if ((sphere.vertices[v] - value).squaredNorm() <
        (sphere.vertices[nearest] - value).squaredNorm())
      nearest = v;
  if (sphere.branch_value[nearest] < 0) {
    sphere.vertices[nearest] = value;
    sphere.branch_value[nearest] = index;
    return;
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
    return;
  }
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

GeodesicSphere geodesic_sphere(int frequency, const std::vector<Eigen::Vector3d> &branch_values) {
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
  for (size_t b = 0; b < distinct.size(); ++b)
    put_on_vertex(out, distinct[b], int(b));
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
