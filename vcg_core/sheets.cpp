#include "sheets.h"

#include <algorithm>
#include <numeric>
#include <queue>

#include "branch_points.h"
#include "sphere_geometry.h"

namespace meromorph {
namespace {

using Vector = Eigen::Vector3d;

// Is x on the minor great-circle arc from a to b?
bool on_arc(const Vector &x, const Vector &a, const Vector &b) {
  const Vector n = a.cross(b);
  return a.cross(x).dot(n) >= 0 && x.cross(b).dot(n) >= 0 && x.dot(a + b) > 0;
}

bool arcs_cross(const Vector &a1, const Vector &a2, const Vector &b1, const Vector &b2) {
  const Vector p = a1.cross(a2).cross(b1.cross(b2));
  if (p.norm() < 1e-300) return false;
  const Vector unit = p.normalized();
  for (const Vector &x : {unit, Vector(-unit)})
    if (on_arc(x, a1, a2) && on_arc(x, b1, b2)) return true;
  return false;
}

// Is x inside the (small, positively oriented) spherical triangle a, b, c?
bool inside(const Vector &x, const Vector &a, const Vector &b, const Vector &c) {
  return a.cross(b).dot(x) >= 0 && b.cross(c).dot(x) >= 0 && c.cross(a).dot(x) >= 0 &&
         x.dot(a + b + c) > 0;
}

} // namespace

Sheets label_sheets(const Mesh &mesh, const MeshEdges &edges, const std::vector<Vector> &sphere,
                    const std::vector<int> &branch_vertices, int degree) {
  Sheets out;
  const int face_count = int(mesh.face.size());
  out.face_layer.assign(face_count, 0);
  out.vertex_layer.assign(mesh.vert.size(), 0);
  auto corner = [&](int f, int k) -> const Vector & {
    return sphere[index_of(mesh, mesh.face[f].cV(k))];
  };
  const std::vector<double> areas = face_solid_angles(mesh, sphere);

  if (degree <= 1 || branch_vertices.empty()) {
    out.count = 1;
    out.coverage = {std::accumulate(areas.begin(), areas.end(), 0.0) / (4 * M_PI)};
    return out;
  }

  // Branch values, and the star point: the direction farthest from all of them.
  std::vector<Vector> values;
  for (int v : branch_vertices)
    values.push_back(sphere[v]);
  Vector star(0, 0, 1);
  double best = -2;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j)
      for (int k = -2; k <= 2; ++k) {
        if (!i && !j && !k) continue;
        const Vector candidate = Vector(i + 0.123, j + 0.0456, k + 0.0789).normalized();
        double nearest = 2;
        for (const Vector &b : values)
          nearest = std::min(nearest, 1 - candidate.dot(b));
        if (nearest > best) {
          best = nearest;
          star = candidate;
        }
      }

  // Faces at a branch vertex always meet its cut (the image of the vertex is where the cut starts;
  // testing that corner as a point inside the face is at the mercy of rounding).
  std::vector<char> cut(face_count, 0), at_branch_vertex(mesh.vert.size(), 0);
  for (int v : branch_vertices)
    at_branch_vertex[v] = 1;
  for (int f = 0; f < face_count; ++f) {
    for (int k = 0; k < 3; ++k)
      if (at_branch_vertex[index_of(mesh, mesh.face[f].cV(k))]) cut[f] = 1;
    if (cut[f]) {
      ++out.cut_faces;
      continue;
    }
    const Vector &a = corner(f, 0), &b = corner(f, 1), &c = corner(f, 2);
    bool hit = inside(star, a, b, c);
    for (const Vector &value : values) {
      if (hit) break;
      hit = inside(value, a, b, c) || arcs_cross(a, b, value, star) ||
            arcs_cross(b, c, value, star) || arcs_cross(c, a, value, star);
    }
    cut[f] = hit || folded_image(a, b, c);
    out.cut_faces += cut[f];
  }

  // Components of the uncut faces.
  std::vector<int> component(face_count, -1);
  std::vector<double> component_area;
  for (int seed = 0; seed < face_count; ++seed) {
    if (cut[seed] || component[seed] >= 0) continue;
    const int id = int(component_area.size());
    component_area.push_back(0);
    std::queue<int> queue;
    queue.push(seed);
    component[seed] = id;
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop();
      component_area[id] += areas[f];
      for (int e : edges.face_edges[f]) {
        const int g = edges.faces[e][0] == f ? edges.faces[e][1] : edges.faces[e][0];
        if (!cut[g] && component[g] < 0) {
          component[g] = id;
          queue.push(g);
        }
      }
    }
  }
  // The largest components are the sheets; the rest (and the cut faces) join a neighbour.
  std::vector<int> order(component_area.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return component_area[a] > component_area[b]; });
  out.count = std::min<int>(degree, int(order.size()));
  std::vector<int> layer_of(component_area.size(), -1);
  for (int i = 0; i < out.count; ++i)
    layer_of[order[i]] = i;
  std::queue<int> frontier;
  std::vector<int> face_layer(face_count, -1);
  for (int f = 0; f < face_count; ++f)
    if (component[f] >= 0 && layer_of[component[f]] >= 0) {
      face_layer[f] = layer_of[component[f]];
      frontier.push(f);
    }
  while (!frontier.empty()) {
    const int f = frontier.front();
    frontier.pop();
    for (int e : edges.face_edges[f]) {
      const int g = edges.faces[e][0] == f ? edges.faces[e][1] : edges.faces[e][0];
      if (face_layer[g] < 0) {
        face_layer[g] = face_layer[f];
        frontier.push(g);
      }
    }
  }
  out.face_layer = face_layer;
  out.coverage.assign(out.count, 0.0);
  for (int f = 0; f < face_count; ++f)
    out.coverage[face_layer[f]] += areas[f] / (4 * M_PI);

  // A vertex takes the layer most of its faces have.
  std::vector<std::vector<int>> votes(mesh.vert.size(), std::vector<int>(out.count, 0));
  for (int f = 0; f < face_count; ++f)
    for (int k = 0; k < 3; ++k)
      ++votes[index_of(mesh, mesh.face[f].cV(k))][face_layer[f]];
  for (size_t v = 0; v < mesh.vert.size(); ++v)
    out.vertex_layer[v] =
        int(std::max_element(votes[v].begin(), votes[v].end()) - votes[v].begin());
  return out;
}

} // namespace meromorph
