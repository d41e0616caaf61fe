#include "sphere/sheets.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <queue>

#include "common/parallel_for.h"
#include "sphere/arc_grid.h"
#include "sphere/branch_points.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {
namespace {

using Vector = Eigen::Vector3d;

constexpr double unsure_edge_length = 1e-6;

// Edges whose image is at most this chord are tested against the cuts near them only.
constexpr double short_edge_image = 0.1;

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

namespace {

// A tree on the sphere through every branch value: its nodes and its arcs (pairs of node indices).
struct CutTree {
  std::vector<Vector> nodes;
  std::vector<std::array<int, 2>> arcs;
};

// The minimum spanning tree of the branch values: the shortest tree, so the fewest faces cut.
CutTree minimum_spanning_tree(const std::vector<Vector> &values) {
  CutTree tree{values, {}};
  const size_t n = values.size();
  std::vector<char> joined(n, 0);
  std::vector<double> distance(n, 1e300);
  std::vector<int> parent(n, -1);
  distance[0] = 0;
  for (size_t step = 0; step < n; ++step) {
    size_t next = n;
    for (size_t i = 0; i < n; ++i)
      if (!joined[i] && (next == n || distance[i] < distance[next])) next = i;
    joined[next] = 1;
    if (parent[next] >= 0) tree.arcs.push_back({parent[next], int(next)});
    for (size_t i = 0; i < n; ++i) {
      const double d = (values[i] - values[next]).norm();
      if (!joined[i] && d < distance[i]) {
        distance[i] = d;
        parent[i] = int(next);
      }
    }
  }
  return tree;
}

// Directions of a grid over the sphere, farthest from every branch value first.
std::vector<Vector> directions_away_from(const std::vector<Vector> &values) {
  std::vector<std::pair<double, Vector>> directions;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j)
      for (int k = -2; k <= 2; ++k) {
        if (!i && !j && !k) continue;
        const Vector candidate = Vector(i + 0.123, j + 0.0456, k + 0.0789).normalized();
        double nearest = 2;
        for (const Vector &b : values)
          nearest = std::min(nearest, 1 - candidate.dot(b));
        directions.push_back({-nearest, candidate});
      }
  std::sort(directions.begin(), directions.end(),
            [](const auto &a, const auto &b) { return a.first < b.first; });
  std::vector<Vector> sorted;
  for (const auto &[distance, direction] : directions)
    sorted.push_back(direction);
  return sorted;
}

// A star: every branch value joined to `star`.
CutTree star_tree(const std::vector<Vector> &values, const Vector &star) {
  CutTree tree{values, {}};
  tree.nodes.push_back(star);
  for (size_t i = 0; i < values.size(); ++i)
    tree.arcs.push_back({int(i), int(values.size())});
  return tree;
}

// Which edges the sheets are cut along.
struct CutEdges {
  std::vector<char> crossing; // the edge's image crosses a cut, or may (it starts on one)
  std::vector<char> cut;      // those, and the edges of the faces set apart
};

// The tree's arcs as the normals of their great circles and their lengths (the normals' norms).
struct ArcPlanes {
  std::vector<Vector> normal;
  std::vector<double> length;
};

ArcPlanes arc_planes(const CutTree &tree) {
  ArcPlanes planes;
  for (const auto &arc : tree.arcs) {
    planes.normal.push_back(tree.nodes[size_t(arc[0])].cross(tree.nodes[size_t(arc[1])]));
    planes.length.push_back(planes.normal.back().norm());
  }
  return planes;
}

// A vertex whose image lies on a cut (symmetric meshes map whole rows of vertices onto the arcs
// between branch values) leaves it to rounding which side its edges are on: those are cut.
std::vector<char> vertices_on_cuts(const std::vector<Vector> &sphere, const CutTree &tree,
                                   const ArcPlanes &planes, const ArcGrid &near_arcs) {
  std::vector<char> on_cut(sphere.size(), 0);
  parallel_for(sphere.size(), [&](size_t v) {
    for (const int arc : near_arcs.near(sphere[v])) {
      const size_t a = size_t(arc);
      const Vector &p = tree.nodes[size_t(tree.arcs[a][0])],
                   &q = tree.nodes[size_t(tree.arcs[a][1])];
      const double length = planes.length[a];
      if (length > 0 && std::abs(sphere[v].dot(planes.normal[a])) < 1e-12 * length &&
          on_arc(sphere[v], p, q))
        on_cut[v] = 1;
    }
  });
  return on_cut;
}

// Per edge: its image crosses a cut, or may (it starts on one, or at a branch vertex). Each
// short edge is tested against the arcs near it only (arc_grid.h), a longer edge against every
// arc.
std::vector<char> edges_crossing_cuts(const MeshEdges &edges, const std::vector<Vector> &sphere,
                                      const CutTree &tree, const ArcPlanes &planes,
                                      const ArcGrid &near_arcs,
                                      const std::vector<char> &at_branch_vertex,
                                      const std::vector<char> &on_cut) {
  std::vector<int> every_arc(tree.arcs.size());
  std::iota(every_arc.begin(), every_arc.end(), 0);
  std::vector<char> crossing(edges.vertices.size(), 0);
  parallel_for(edges.vertices.size(), [&](size_t e) {
    const int i = edges.vertices[e][0], j = edges.vertices[e][1];
    crossing[e] = at_branch_vertex[i] || at_branch_vertex[j] || on_cut[i] || on_cut[j];
    const std::vector<int> &candidates =
        (sphere[i] - sphere[j]).norm() <= short_edge_image ? near_arcs.near(sphere[i]) : every_arc;
    for (size_t k = 0; k < candidates.size() && !crossing[e]; ++k) {
      const size_t a = size_t(candidates[k]);
      // Both ends clearly on one side of the arc's great circle: no crossing (far above rounding).
      const double side_i = sphere[i].dot(planes.normal[a]),
                   side_j = sphere[j].dot(planes.normal[a]);
      const double margin = 1e-9 * planes.length[a];
      if ((side_i > margin && side_j > margin) || (side_i < -margin && side_j < -margin)) continue;
      crossing[e] = arcs_cross(sphere[i], sphere[j], tree.nodes[size_t(tree.arcs[a][0])],
                               tree.nodes[size_t(tree.arcs[a][1])]);
    }
  });
  return crossing;
}

// Faces set apart: those at a branch vertex, those whose image holds a node of the tree, and
// folded ones (see cut_edges).
std::vector<int> faces_set_apart(const Mesh &mesh, const std::vector<Vector> &sphere,
                                 const std::vector<Vector> &nodes,
                                 const std::vector<char> &at_branch_vertex) {
  auto corner = [&](int f, int k) -> const Vector & {
    return sphere[index_of(mesh, mesh.face[f].cV(k))];
  };
  return parallel_select(mesh.face.size(), [&](size_t f) {
    for (int k = 0; k < 3; ++k)
      if (at_branch_vertex[index_of(mesh, mesh.face[f].cV(k))]) return true;
    const Vector &a = corner(int(f), 0), &b = corner(int(f), 1), &c = corner(int(f), 2);
    // A node inside the face is within its longest side of a (twice that, to be safe on the
    // sphere): the rest are passed over with one subtraction and one product.
    const double reach =
        4 * std::max({(a - b).squaredNorm(), (b - c).squaredNorm(), (c - a).squaredNorm()});
    for (const Vector &node : nodes)
      if ((node - a).squaredNorm() <= reach && inside(node, a, b, c)) return true;
    return folded_image(a, b, c);
  });
}

// Two faces lie on the same sheet where the image of their shared edge crosses no cut. Faces at
// a branch vertex are set apart (cuts start at their corner, and a branch point doubles their
// angles there: the image of the opposite side can span half a turn, too much for a minor arc),
// faces whose image holds a node of the tree (a branch value: where flat faces next to a branch
// vertex leave a gap, a cut starts inside another face; or a star's centre), and folded faces
// (they have no side). Faces whose image meets a cut are counted (`cut_faces`).
CutEdges cut_edges(const Mesh &mesh, const MeshEdges &edges, const std::vector<Vector> &sphere,
                   const std::vector<int> &branch_vertices, const CutTree &tree) {
  std::vector<char> at_branch_vertex(mesh.vert.size(), 0);
  for (int v : branch_vertices)
    at_branch_vertex[v] = 1;
  const ArcPlanes planes = arc_planes(tree);
  const ArcGrid near_arcs(tree.nodes, tree.arcs, short_edge_image);
  const std::vector<char> on_cut = vertices_on_cuts(sphere, tree, planes, near_arcs);
  CutEdges out;
  out.crossing =
      edges_crossing_cuts(edges, sphere, tree, planes, near_arcs, at_branch_vertex, on_cut);
  // Edges whose image is too short for the crossing test to be sure of its side (where long thin
  // parts crowd, cross products of such nearby points are mostly rounding) are cut too, so that a
  // sheet cannot leak into another through them; and the edges of the faces set apart.
  out.cut = out.crossing;
  std::vector<char> &edge_cut = out.cut;
  parallel_for(edges.vertices.size(), [&](size_t e) {
    if ((sphere[size_t(edges.vertices[e][0])] - sphere[size_t(edges.vertices[e][1])]).norm() <
        unsure_edge_length)
      edge_cut[e] = 1;
  });
  for (int f : faces_set_apart(mesh, sphere, tree.nodes, at_branch_vertex))
    for (int e : edges.face_edges[size_t(f)])
      edge_cut[size_t(e)] = 1;
  return out;
}

// Components of faces joined across uncut edges, and each component's image area.
std::vector<int> face_components(const MeshEdges &edges, const std::vector<char> &edge_cut,
                                 const std::vector<double> &areas,
                                 std::vector<double> &component_area) {
  const int face_count = int(areas.size());
  std::vector<int> component(face_count, -1);
  for (int seed = 0; seed < face_count; ++seed) {
    if (component[seed] >= 0) continue;
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
        if (!edge_cut[e] && component[g] < 0) {
          component[g] = id;
          queue.push(g);
        }
      }
    }
  }
  return component;
}

// The largest components are the sheets (at most `degree`); the rest (and the cut faces) join
// a neighbour. Returns the layer per face; `count` gets the number of sheets.
std::vector<int> face_layers(const MeshEdges &edges, const std::vector<int> &component,
                             const std::vector<double> &component_area,
                             const std::vector<char> &crossing, int degree, int &count) {
  const int face_count = int(component.size());
  std::vector<int> order(component_area.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return component_area[a] > component_area[b]; });
  count = std::min<int>(degree, int(order.size()));
  std::vector<int> layer_of(component_area.size(), -1);
  for (int i = 0; i < count; ++i)
    layer_of[order[i]] = i;
  std::queue<int> frontier;
  std::vector<int> face_layer(face_count, -1);
  for (int f = 0; f < face_count; ++f)
    if (component[f] >= 0 && layer_of[component[f]] >= 0) face_layer[f] = layer_of[component[f]];
  // The faces set apart join their sheets across edges whose image crosses no cut first, so that a
  // strip between two close cuts goes to the sheet it continues; what is left, across any edge.
  for (const bool across_cuts : {false, true}) {
    for (int f = 0; f < face_count; ++f)
      if (face_layer[f] >= 0) frontier.push(f);
    while (!frontier.empty()) {
      const int f = frontier.front();
      frontier.pop();
      for (int e : edges.face_edges[f]) {
        const int g = edges.faces[e][0] == f ? edges.faces[e][1] : edges.faces[e][0];
        if (face_layer[g] < 0 && (across_cuts || !crossing[e])) {
          face_layer[g] = face_layer[f];
          frontier.push(g);
        }
      }
    }
  }
  return face_layer;
}

// Layers of a degree-d map (d >= 2) cut along `tree`.
Sheets label_with_cuts(const Mesh &mesh, const MeshEdges &edges, const std::vector<Vector> &sphere,
                       const std::vector<int> &branch_vertices, int degree,
                       const std::vector<double> &areas, const CutTree &tree) {
  Sheets out;
  const int face_count = int(mesh.face.size());
  out.vertex_layer.assign(mesh.vert.size(), 0);
  const CutEdges cuts = cut_edges(mesh, edges, sphere, branch_vertices, tree);
  for (int f = 0; f < face_count; ++f) {
    const auto &sides = edges.face_edges[f];
    out.cut_faces += cuts.cut[sides[0]] || cuts.cut[sides[1]] || cuts.cut[sides[2]];
  }
  std::vector<double> component_area;
  const std::vector<int> component = face_components(edges, cuts.cut, areas, component_area);
  const std::vector<int> face_layer =
      face_layers(edges, component, component_area, cuts.crossing, degree, out.count);
  out.face_layer = face_layer;
  out.coverage.assign(out.count, 0.0);
  for (int f = 0; f < face_count; ++f)
    out.coverage[face_layer[f]] += areas[f] / (4 * M_PI);

  // A vertex takes the layer most of its faces have.
  const size_t layers = size_t(out.count);
  std::vector<int> votes(mesh.vert.size() * layers, 0); // per vertex, per layer
  for (int f = 0; f < face_count; ++f)
    for (int k = 0; k < 3; ++k)
      ++votes[size_t(index_of(mesh, mesh.face[f].cV(k))) * layers + size_t(face_layer[f])];
  for (size_t v = 0; v < mesh.vert.size(); ++v) {
    const auto first = votes.begin() + long(v * layers);
    out.vertex_layer[v] = int(std::max_element(first, first + long(layers)) - first);
  }
  return out;
}

} // namespace

Sheets label_sheets(const Mesh &mesh, const MeshEdges &edges, const std::vector<Vector> &sphere,
                    const std::vector<int> &branch_vertices, int degree) {
  const std::vector<double> areas = face_solid_angles(mesh, sphere);
  if (degree <= 1 || branch_vertices.empty()) {
    Sheets out;
    out.count = 1;
    out.face_layer.assign(mesh.face.size(), 0);
    out.vertex_layer.assign(mesh.vert.size(), 0);
    out.coverage = {std::accumulate(areas.begin(), areas.end(), 0.0) / (4 * M_PI)};
    return out;
  }
  // Cut along the shortest tree; where its layers do not each cover the sphere once (a sheet that
  // comes out in two pieces, seen with nearly equal branch values), along stars from the six
  // directions farthest from every branch value as well, and keep the best.
  std::vector<Vector> values;
  for (int v : branch_vertices)
    values.push_back(sphere[v]);
  auto worst = [](const Sheets &sheets) {
    double deviation = 0;
    for (double c : sheets.coverage)
      deviation = std::max(deviation, std::abs(c - 1));
    return deviation;
  };
  Sheets sheets = label_with_cuts(mesh, edges, sphere, branch_vertices, degree, areas,
                                  minimum_spanning_tree(values));
  const std::vector<Vector> directions = directions_away_from(values);
  for (size_t rank = 0; rank < 6 && worst(sheets) > 0.02; ++rank) {
    Sheets star = label_with_cuts(mesh, edges, sphere, branch_vertices, degree, areas,
                                  star_tree(values, directions[rank]));
    if (worst(star) < worst(sheets)) sheets = std::move(star);
  }
  return sheets;
}

} // namespace meromorph
