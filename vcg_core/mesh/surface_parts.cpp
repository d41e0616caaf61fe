#include "mesh/surface_parts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

#include "common/errors.h"
#include "mesh/mesh_edges.h"

namespace meromorph {
namespace {

int find_root(std::vector<int> &parent, int x) {
  while (parent[size_t(x)] != x) {
    parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
    x = parent[size_t(x)];
  }
  return x;
}

// Closes a hole: rings of vertices shrinking towards the loop's centroid, about one ring per
// 2 pi edges of the loop and fewer vertices the smaller a ring is, zipped together by their
// arc-length parameter, and a fan at the centre (a loop of three edges: one triangle, unless
// the part is that one triangle: then a fan from its centroid, not the same face again); so the
// triangles stay about as large as the loop's edges (a plain fan from the centroid would make long
// needles on a large hole). A face walks a boundary edge a -> b; the faces closing it walk b -> a.
void close_loop(const std::vector<int> &loop, std::vector<Point3> &positions,
                std::vector<std::array<int, 3>> &triangles) {
  const size_t n = loop.size();
  if (n == 3 && triangles.size() > 1) { // one triangle, no new vertex
    triangles.push_back({loop[2], loop[1], loop[0]});
    return;
  }
  Point3 centre(0, 0, 0);
  std::vector<double> arc(n + 1, 0.0); // arc length to loop vertex i, arc[n]: the whole loop
  for (size_t i = 0; i < n; ++i) {
    centre += positions[size_t(loop[i])];
    arc[i + 1] =
        arc[i] + (positions[size_t(loop[(i + 1) % n])] - positions[size_t(loop[i])]).Norm();
  }
  centre /= double(n);
  // At extreme scales (1e-300, 1e200) squared lengths underflow or overflow: measure relative to
  // the loop's extent then, and where even that gives no finite length, by vertex count.
  if (!(arc[n] > 0 && std::isfinite(arc[n]))) {
    double extent = 0;
    for (int v : loop)
      for (int axis = 0; axis < 3; ++axis)
        extent = std::max(extent, std::abs(positions[size_t(v)][axis] - centre[axis]));
    for (size_t i = 0; i < n; ++i) {
      const Point3 side = positions[size_t(loop[(i + 1) % n])] - positions[size_t(loop[i])];
      arc[i + 1] = arc[i] + (extent > 0 && std::isfinite(extent) ? (side / extent).Norm() : 0.0);
    }
    if (!(arc[n] > 0 && std::isfinite(arc[n])))
      for (size_t i = 0; i <= n; ++i)
        arc[i] = double(i);
  }
  const auto on_loop = [&](double s) { // the point at arc-length fraction s of the loop
    const double at = s * arc[n];
    size_t i = 0;
    while (i + 1 < n && arc[i + 1] < at)
      ++i;
    const double t = arc[i + 1] > arc[i] ? (at - arc[i]) / (arc[i + 1] - arc[i]) : 0.0;
    return positions[size_t(loop[i])] * (1 - t) + positions[size_t(loop[(i + 1) % n])] * t;
  };
  std::vector<int> outer = loop;
  std::vector<double> outer_param(n);
  for (size_t i = 0; i < n; ++i)
    outer_param[i] = arc[i] / arc[n];
  const int rings = std::max(1, int(std::lround(double(n) / (2 * M_PI))));
  for (int r = 1; r <= rings; ++r) {
    const double scale = 1.0 - double(r) / rings;
    const size_t count =
        r == rings ? 1 : std::max<size_t>(3, size_t(std::lround(double(n) * scale)));
    std::vector<int> inner;
    std::vector<double> inner_param;
    for (size_t j = 0; j < count; ++j) {
      const double s = double(j) / double(count);
      inner.push_back(int(positions.size()));
      inner_param.push_back(s);
      positions.push_back(centre + (on_loop(s) - centre) * scale);
    }
    if (count == 1) {
      for (size_t i = 0; i < outer.size(); ++i)
        triangles.push_back({outer[(i + 1) % outer.size()], outer[i], inner[0]});
      break;
    }
    // Zip the two rings: advance the one whose next vertex comes first around the loop.
    size_t i = 0, j = 0;
    while (i < outer.size() || j < inner.size()) {
      const double next_outer =
          i < outer.size() ? (i + 1 < outer.size() ? outer_param[i + 1] : 1.0) : 2.0;
      const double next_inner =
          j < inner.size() ? (j + 1 < inner.size() ? inner_param[j + 1] : 1.0) : 2.0;
      const int o = outer[i % outer.size()], m = inner[j % inner.size()];
      if (next_outer <= next_inner) {
        triangles.push_back({outer[(i + 1) % outer.size()], o, m});
        ++i;
      } else {
        triangles.push_back({o, m, inner[(j + 1) % inner.size()]});
        ++j;
      }
    }
    outer = std::move(inner);
    outer_param = std::move(inner_param);
  }
}

// Parts: faces joined across shared edges (union-find over the edges' faces). Fills each face's
// and vertex's part and the face's place in it; returns the faces of each part.
std::vector<std::vector<int>> faces_by_part(const std::vector<std::array<int, 3>> &corners,
                                            int vertex_count, SurfaceParts &out) {
  const int face_count = int(corners.size());
  std::vector<int> parent(static_cast<size_t>(face_count));
  std::iota(parent.begin(), parent.end(), 0);
  std::map<std::pair<int, int>, int> first_face_of_edge;
  for (int f = 0; f < face_count; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = corners[size_t(f)][k], b = corners[size_t(f)][(k + 1) % 3];
      const auto [it, inserted] = first_face_of_edge.insert({{std::min(a, b), std::max(a, b)}, f});
      if (!inserted) parent[size_t(find_root(parent, f))] = find_root(parent, it->second);
    }
  out.part_of_face.assign(size_t(face_count), -1);
  out.face_in_part.assign(size_t(face_count), -1);
  out.part_of_vertex.assign(size_t(vertex_count), -1);
  out.vertex_in_part.assign(size_t(vertex_count), -1);
  std::vector<int> part_of_root(static_cast<size_t>(face_count), -1);
  std::vector<std::vector<int>> faces_of_part;
  for (int f = 0; f < face_count; ++f) {
    int &part = part_of_root[size_t(find_root(parent, f))];
    if (part < 0) {
      part = int(faces_of_part.size());
      faces_of_part.emplace_back();
    }
    out.part_of_face[size_t(f)] = part;
    out.face_in_part[size_t(f)] = int(faces_of_part[size_t(part)].size());
    faces_of_part[size_t(part)].push_back(f);
  }
  for (int f = 0; f < face_count; ++f)
    for (int v : corners[size_t(f)])
      out.part_of_vertex[size_t(v)] = out.part_of_face[size_t(f)];
  return faces_of_part;
}

// Closes every hole of part p (its triangles and positions grow), recording each in `out.holes`.
void close_part_holes(size_t p, SurfacePart &part, std::vector<std::array<int, 3>> &triangles,
                      std::vector<Point3> &positions, SurfaceParts &out) {
  const BoundaryLoops boundary = chain_boundary(triangles);
  if (boundary.pinched_vertex >= 0)
    throw InputError("a hole's boundary passes vertex " +
                     std::to_string(part.source_vertex[size_t(boundary.pinched_vertex)]) +
                     " twice (two holes touch there): it cannot be closed; separate them first");
  for (const std::vector<int> &loop : boundary.loops) {
    ClosedHole hole;
    hole.part = int(p);
    hole.edges = int(loop.size());
    hole.vertex = part.source_vertex[size_t(loop.front())];
    const size_t first_face = triangles.size();
    close_loop(loop, positions, triangles);
    for (size_t f = first_face; f < triangles.size(); ++f) {
      hole.faces.push_back(int(f));
      part.source_face.push_back(-1);
    }
    part.source_vertex.resize(positions.size(), -1);
    out.holes.push_back(std::move(hole));
  }
}

} // namespace

SurfaceParts split_into_closed_parts(const Mesh &input, bool close_holes) {
  const int face_count = int(input.face.size()), vertex_count = int(input.vert.size());
  std::vector<std::array<int, 3>> corners(static_cast<size_t>(face_count));
  for (int f = 0; f < face_count; ++f)
    for (int k = 0; k < 3; ++k)
      corners[size_t(f)][k] = index_of(input, input.face[size_t(f)].cV(k));
  SurfaceParts out;
  const std::vector<std::vector<int>> faces_of_part = faces_by_part(corners, vertex_count, out);
  out.parts.resize(faces_of_part.size());
  for (int v = 0; v < vertex_count; ++v) // each part's vertices, in the input's order
    if (out.part_of_vertex[size_t(v)] >= 0) {
      SurfacePart &part = out.parts[size_t(out.part_of_vertex[size_t(v)])];
      out.vertex_in_part[size_t(v)] = int(part.source_vertex.size());
      part.source_vertex.push_back(v);
    }
  for (size_t p = 0; p < faces_of_part.size(); ++p) {
    SurfacePart &part = out.parts[p];
    std::vector<std::array<int, 3>> triangles;
    for (int f : faces_of_part[p]) {
      std::array<int, 3> t;
      for (int k = 0; k < 3; ++k)
        t[k] = out.vertex_in_part[size_t(corners[size_t(f)][k])];
      triangles.push_back(t);
      part.source_face.push_back(f);
    }
    std::vector<Point3> positions;
    for (int v : part.source_vertex)
      positions.push_back(input.vert[size_t(v)].cP());
    if (close_holes) close_part_holes(p, part, triangles, positions, out);
    auto vi = vcg::tri::Allocator<Mesh>::AddVertices(part.mesh, positions.size());
    for (size_t v = 0; v < positions.size(); ++v, ++vi)
      vi->P() = positions[v];
    for (const auto &t : triangles)
      vcg::tri::Allocator<Mesh>::AddFace(part.mesh, &part.mesh.vert[size_t(t[0])],
                                         &part.mesh.vert[size_t(t[1])],
                                         &part.mesh.vert[size_t(t[2])]);
  }
  return out;
}

} // namespace meromorph
