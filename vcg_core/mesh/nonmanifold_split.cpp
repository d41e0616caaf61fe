#include "mesh/nonmanifold_split.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>

#include <Eigen/Geometry>

#include "mesh/mesh_from_arrays.h"

namespace meromorph {
namespace {

struct CornerSets {
  std::vector<int> parent;
  explicit CornerSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int root(int c) {
    while (parent[size_t(c)] != c)
      c = parent[size_t(c)] = parent[size_t(parent[size_t(c)])];
    return c;
  }
  void join(int a, int b) { parent[size_t(root(a))] = root(b); }
};

struct EdgeUse {
  int low, high, face, from; // from: the face's corner where the edge starts
  int from_vertex(const MeshArrays &mesh) const {
    return mesh.triangles[size_t(face)][size_t(from)];
  }
  bool operator<(const EdgeUse &o) const {
    return std::tie(low, high, face, from) < std::tie(o.low, o.high, o.face, o.from);
  }
};

bool repeats_vertex(const std::array<int, 3> &t) {
  return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
}

Eigen::Vector3d position(const MeshArrays &mesh, int v) {
  return mesh.positions[size_t(v)].ToEigenVector<Eigen::Vector3d>();
}

// Around one edge with more than two faces: for each face, the face it is glued to (-1: none).
std::vector<int> partners_around_edge(const MeshArrays &mesh, const std::vector<EdgeUse> &uses) {
  const size_t n = uses.size();
  std::vector<int> partner(n, -1);
  const Eigen::Vector3d a = position(mesh, uses[0].low);
  Eigen::Vector3d axis = position(mesh, uses[0].high) - a;
  if (!(axis.norm() > 0)) return partner;
  axis.normalize();
  const Eigen::Vector3d u1 = axis.unitOrthogonal(), u2 = axis.cross(u1);
  std::vector<double> angle(n);
  std::vector<int> turn(n); // +1: the face's back (inside) is towards increasing angle
  for (size_t i = 0; i < n; ++i) {
    const auto &t = mesh.triangles[size_t(uses[i].face)];
    const Eigen::Vector3d p0 = position(mesh, t[0]), p1 = position(mesh, t[1]),
                          p2 = position(mesh, t[2]);
    const Eigen::Vector3d d = position(mesh, t[size_t((uses[i].from + 2) % 3)]) - a;
    const Eigen::Vector3d normal = (p1 - p0).cross(p2 - p0);
    const double side = axis.cross(d).dot(normal);
    if (!(std::abs(side) > 0)) return partner; // a flat or degenerate face: leave all apart
    angle[i] = std::atan2(d.dot(u2), d.dot(u1));
    turn[i] = side < 0 ? 1 : -1;
  }
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return angle[i] < angle[j]; });
  std::vector<size_t> place(n);
  for (size_t k = 0; k < n; ++k)
    place[order[k]] = k;
  auto neighbour = [&](size_t i) {
    return order[turn[i] > 0 ? (place[i] + 1) % n : (place[i] + n - 1) % n];
  };
  for (size_t i = 0; i < n; ++i) {
    const size_t j = neighbour(i);
    const bool opposite_directions = uses[i].from_vertex(mesh) != uses[j].from_vertex(mesh);
    if (j != i && neighbour(j) == i && opposite_directions) partner[i] = int(j);
  }
  return partner;
}

// Every face's sides (faces with a repeated vertex have none), sorted so that the uses of one
// edge are next to each other.
std::vector<EdgeUse> sorted_edge_uses(const MeshArrays &mesh) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto &t = mesh.triangles[f];
    if (repeats_vertex(t)) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = t[size_t(k)], b = t[size_t((k + 1) % 3)];
      uses.push_back({std::min(a, b), std::max(a, b), int(f), k});
    }
  }
  std::sort(uses.begin(), uses.end());
  return uses;
}

// Face corners joined into sets, one set per vertex of the split mesh: two faces glued along an
// edge share the corners at both its ends.
struct CornerGluing {
  const MeshArrays &mesh;
  CornerSets corners;
  explicit CornerGluing(const MeshArrays &m) : mesh(m), corners(3 * m.triangles.size()) {}

  int corner_at(const EdgeUse &use, int vertex) const {
    const auto &t = mesh.triangles[size_t(use.face)];
    const int k = t[0] == vertex ? 0 : t[1] == vertex ? 1 : 2;
    return 3 * use.face + k;
  }
  int set_at(const EdgeUse &use, int vertex) { return corners.root(corner_at(use, vertex)); }
  void glue(const EdgeUse &one, const EdgeUse &other) {
    for (int vertex : {one.low, one.high})
      corners.join(corner_at(one, vertex), corner_at(other, vertex));
  }

  // Per face around an edge, the (at most two) first other faces whose fan meets its own at an
  // end of the edge, in increasing order: enough to tell none, one, or more. Linear in the
  // number of faces (up to sorting), however many share the edge.
  std::vector<std::vector<size_t>> joined_through_fans(const std::vector<EdgeUse> &around) {
    const size_t n = around.size();
    std::array<std::vector<std::pair<int, size_t>>, 2> by_set; // (set at the end, face), sorted
    for (int end = 0; end < 2; ++end) {
      for (size_t i = 0; i < n; ++i)
        by_set[size_t(end)].push_back(
            {set_at(around[i], end == 0 ? around[i].low : around[i].high), i});
      std::sort(by_set[size_t(end)].begin(), by_set[size_t(end)].end());
    }
    std::vector<std::vector<size_t>> joined(n);
    for (size_t i = 0; i < n; ++i) {
      std::vector<size_t> found;
      for (int end = 0; end < 2; ++end) {
        const auto &sets = by_set[size_t(end)];
        const int set = set_at(around[i], end == 0 ? around[i].low : around[i].high);
        size_t taken = 0;
        for (auto at = std::lower_bound(sets.begin(), sets.end(), std::make_pair(set, size_t(0)));
             at != sets.end() && at->first == set && taken < 2; ++at)
          if (at->second != i) {
            found.push_back(at->second);
            ++taken;
          }
      }
      std::sort(found.begin(), found.end());
      found.erase(std::unique(found.begin(), found.end()), found.end());
      if (found.size() > 2) found.resize(2);
      joined[i] = std::move(found);
    }
    return joined;
  }

  // Around an edge with more than two faces: two faces whose fans already meet at an end of the
  // edge must be glued to each other (else the edge keeps more than two faces); the others are
  // paired by their geometry.
  void glue_crowded_edge(const std::vector<EdgeUse> &around) {
    const std::vector<std::vector<size_t>> joined = joined_through_fans(around);
    const size_t n = around.size();
    std::vector<EdgeUse> free;
    for (size_t i = 0; i < n; ++i) {
      if (joined[i].empty()) free.push_back(around[i]);
      const size_t j = joined[i].empty() ? i : joined[i][0];
      if (joined[i].size() == 1 && joined[j].size() == 1 && i < j &&
          around[i].from_vertex(mesh) != around[j].from_vertex(mesh))
        glue(around[i], around[j]);
    }
    if (free.size() < 2) return;
    const std::vector<int> partner = partners_around_edge(mesh, free);
    for (size_t i = 0; i < free.size(); ++i)
      if (partner[i] > int(i)) glue(free[i], free[size_t(partner[i])]);
  }
};

// One vertex per set of glued corners: the input's index for the fan of its first face, a new
// vertex at the same position for every further fan. `mesh` gets the new vertices and corners.
void give_each_fan_a_vertex(MeshArrays &mesh, CornerGluing &gluing, NonmanifoldSplit &out) {
  const size_t vertex_count = mesh.positions.size(), face_count = mesh.triangles.size();
  std::vector<int> vertex_of_set(3 * face_count, -1);
  std::vector<char> claimed(vertex_count, 0), was_split(vertex_count, 0);
  out.source_vertex.resize(vertex_count);
  std::iota(out.source_vertex.begin(), out.source_vertex.end(), 0);
  std::vector<std::array<int, 3>> triangles = mesh.triangles;
  for (size_t f = 0; f < face_count; ++f) {
    if (repeats_vertex(mesh.triangles[f])) continue;
    for (int k = 0; k < 3; ++k) {
      const int vertex = mesh.triangles[f][size_t(k)];
      int &assigned = vertex_of_set[size_t(gluing.corners.root(int(3 * f) + k))];
      if (assigned < 0) {
        if (!claimed[size_t(vertex)]) {
          claimed[size_t(vertex)] = 1;
          assigned = vertex;
        } else {
          assigned = int(mesh.positions.size());
          mesh.positions.push_back(mesh.positions[size_t(vertex)]);
          out.source_vertex.push_back(vertex);
          was_split[size_t(vertex)] = 1;
        }
      }
      triangles[f][size_t(k)] = assigned;
    }
  }
  for (size_t v = 0; v < vertex_count; ++v)
    if (was_split[v]) out.split_vertices.push_back(int(v));
  out.added_vertices = int(mesh.positions.size() - vertex_count);
  mesh.triangles = std::move(triangles);
}

} // namespace

NonmanifoldSplit split_nonmanifold(const Mesh &input, Mesh &split) {
  MeshArrays mesh = arrays_from_mesh(input);
  const std::vector<EdgeUse> uses = sorted_edge_uses(mesh);
  NonmanifoldSplit out;
  CornerGluing gluing(mesh);
  // The faces around each edge; edges with two faces glued first, so that around an edge with
  // more, faces already joined through their fans are known.
  std::vector<std::vector<EdgeUse>> crowded;
  for (size_t begin = 0, end; begin < uses.size(); begin = end) {
    for (end = begin + 1; end < uses.size() && uses[end].low == uses[begin].low &&
                          uses[end].high == uses[begin].high;
         ++end) {
    }
    if (end - begin == 2) gluing.glue(uses[begin], uses[begin + 1]);
    if (end - begin > 2) crowded.emplace_back(uses.begin() + long(begin), uses.begin() + long(end));
  }
  for (const std::vector<EdgeUse> &around : crowded) {
    out.split_edges.push_back({around[0].low, around[0].high});
    gluing.glue_crowded_edge(around);
  }
  give_each_fan_a_vertex(mesh, gluing, out);
  mesh_from_arrays(mesh, split);
  return out;
}

} // namespace meromorph
