#include "forms/homology_basis.h"

#include <algorithm>
#include <functional>
#include <queue>

#include "common/errors.h"

namespace meromorph {
namespace {

// The spanning tree as parent links, from a root, with the edge to the parent.
struct Tree {
  std::vector<int> parent;
  std::vector<int> parent_edge;
};

// Path from `node` up to the root as (edge, node the step leaves).
std::vector<std::pair<int, int>> path_to_root(const Tree &tree, int node) {
  std::vector<std::pair<int, int>> path;
  while (tree.parent[node] >= 0) {
    path.push_back({tree.parent_edge[node], node});
    node = tree.parent[node];
  }
  return path;
}

// Drops the common tail of two root paths (the part above their lowest common ancestor).
void strip_common_tail(std::vector<std::pair<int, int>> &a, std::vector<std::pair<int, int>> &b) {
  while (!a.empty() && !b.empty() && a.back() == b.back()) {
    a.pop_back();
    b.pop_back();
  }
}

// Breadth-first tree of vertices from vertex 0: combinatorial, so a rigid motion or a scale of
// the mesh gives the same loops (a geometric shortest-path tree would break ties differently).
Tree vertex_tree(int vertex_count, const MeshEdges &edges) {
  const IndexLists incident = edges_at_vertices(edges, vertex_count);
  Tree tree{std::vector<int>(vertex_count, -1), std::vector<int>(vertex_count, -1)};
  std::vector<char> seen(vertex_count, 0);
  std::queue<int> frontier;
  frontier.push(0);
  seen[0] = 1;
  while (!frontier.empty()) {
    const int v = frontier.front();
    frontier.pop();
    for (int e : incident[v]) {
      const int w = edges.vertices[e][0] == v ? edges.vertices[e][1] : edges.vertices[e][0];
      if (seen[w]) continue;
      seen[w] = 1;
      tree.parent[w] = v;
      tree.parent_edge[w] = e;
      frontier.push(w);
    }
  }
  for (int v = 1; v < vertex_count; ++v)
    if (tree.parent[v] < 0) throw InputError("the mesh is not connected");
  return tree;
}

// Spanning tree of faces through the edges not in the vertex tree.
Tree face_tree(const MeshEdges &edges, const std::vector<char> &in_vertex_tree) {
  const int face_count = int(edges.face_edges.size());
  Tree tree{std::vector<int>(face_count, -1), std::vector<int>(face_count, -1)};
  std::vector<char> reached(face_count, 0);
  std::queue<int> faces;
  faces.push(0);
  reached[0] = 1;
  while (!faces.empty()) {
    const int f = faces.front();
    faces.pop();
    for (int e : edges.face_edges[f]) {
      if (in_vertex_tree[e]) continue;
      const int g = edges.faces[e][0] == f ? edges.faces[e][1] : edges.faces[e][0];
      if (reached[g]) continue;
      reached[g] = 1;
      tree.parent[g] = f;
      tree.parent_edge[g] = e;
      faces.push(g);
    }
  }
  return tree;
}

std::vector<char> tree_edges(const Tree &tree, int edge_count) {
  std::vector<char> in_tree(edge_count, 0);
  for (int e : tree.parent_edge)
    if (e >= 0) in_tree[e] = 1;
  return in_tree;
}

// Primal loop: along the generator from a to b, then back through the vertex tree.
std::vector<std::pair<int, int>> primal_loop(const MeshEdges &edges, const Tree &vertices,
                                             int generator) {
  const int a = edges.vertices[generator][0], b = edges.vertices[generator][1];
  auto from_b = path_to_root(vertices, b), from_a = path_to_root(vertices, a);
  strip_common_tail(from_b, from_a);
  std::vector<std::pair<int, int>> loop{{generator, +1}};
  for (auto [edge, leaving] : from_b)
    loop.push_back({edge, edges.vertices[edge][0] == leaving ? 1 : -1});
  for (auto it = from_a.rbegin(); it != from_a.rend(); ++it) // down to a: the reverse steps
    loop.push_back({it->first, edges.vertices[it->first][0] == it->second ? -1 : 1});
  return loop;
}

// Dual loop as a 1-form: across the generator from its left face to its right face, then back
// through the face tree. Crossing an edge from its left face to its right face counts +1.
Eigen::SparseVector<double> dual_form(const MeshEdges &edges, const Tree &faces, int generator) {
  std::vector<std::pair<int, double>> crossings{{generator, 1.0}};
  const int left = edges.faces[generator][0], right = edges.faces[generator][1];
  auto from_right = path_to_root(faces, right), from_left = path_to_root(faces, left);
  strip_common_tail(from_right, from_left);
  for (auto [edge, leaving] : from_right)
    crossings.push_back({edge, edges.faces[edge][0] == leaving ? 1.0 : -1.0});
  for (auto [edge, leaving] : from_left)
    crossings.push_back({edge, edges.faces[edge][0] == leaving ? -1.0 : 1.0});
  std::sort(crossings.begin(), crossings.end());
  Eigen::SparseVector<double> form(edges.edge_count());
  form.reserve(long(crossings.size()));
  for (size_t k = 0; k < crossings.size();) {
    const int edge = crossings[k].first;
    double sum = 0;
    for (; k < crossings.size() && crossings[k].first == edge; ++k)
      sum += crossings[k].second;
    if (sum != 0) form.insertBack(edge) = sum;
  }
  return form;
}

} // namespace

double integrate(const Eigen::VectorXd &form, const std::vector<std::pair<int, int>> &loop) {
  double sum = 0;
  for (auto [edge, sign] : loop)
    sum += sign * form[edge];
  return sum;
}

double integrate(const Eigen::SparseVector<double> &form,
                 const std::vector<std::pair<int, int>> &loop) {
  double sum = 0;
  for (auto [edge, sign] : loop)
    sum += sign * form.coeff(edge);
  return sum;
}

HomologyBasis tree_cotree(int vertex_count, const MeshEdges &edges) {
  const int edge_count = edges.edge_count();
  const Tree vertices = vertex_tree(vertex_count, edges);
  const std::vector<char> in_vertex_tree = tree_edges(vertices, edge_count);
  const Tree faces = face_tree(edges, in_vertex_tree);
  const std::vector<char> in_face_tree = tree_edges(faces, edge_count);

  HomologyBasis basis;
  for (int e = 0; e < edge_count; ++e)
    if (!in_vertex_tree[e] && !in_face_tree[e]) basis.generator_edges.push_back(e);
  if (basis.generator_edges.size() % 2 != 0)
    throw InternalError("tree-cotree found an odd number of generators");
  basis.genus = int(basis.generator_edges.size()) / 2;
  for (int generator : basis.generator_edges) {
    basis.primal_loops.push_back(primal_loop(edges, vertices, generator));
    basis.dual_forms.push_back(dual_form(edges, faces, generator));
  }
  return basis;
}

} // namespace meromorph
