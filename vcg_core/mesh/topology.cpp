#include "mesh/topology.h"

#include <algorithm>

#include "mesh/mesh_edges.h"
#include "mesh/validation.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/append.h>

namespace meromorph {

std::vector<char> boundary_vertices(const Mesh &mesh) {
  std::vector<std::pair<int, int>> edges; // undirected, (low, high)
  edges.reserve(3 * mesh.face.size());
  for (const MeshFace &face : mesh.face) {
    if (face.IsD() || face.cV(0) == face.cV(1) || face.cV(1) == face.cV(2) ||
        face.cV(2) == face.cV(0))
      continue;
    for (int k = 0; k < 3; ++k) {
      const int a = index_of(mesh, face.cV(k)), b = index_of(mesh, face.cV((k + 1) % 3));
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<char> boundary(mesh.vert.size(), 0);
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i])
      ++j;
    if (j - i == 1) boundary[size_t(edges[i].first)] = boundary[size_t(edges[i].second)] = 1;
    i = j;
  }
  return boundary;
}

void update_face_adjacency(Mesh &mesh) {
  // The live half-edges h = 3 f + k grouped by their lower vertex (a counting sort), then by
  // their upper one within each vertex's few.
  const size_t half_edges = 3 * mesh.face.size();
  const HalfEdgesByLowVertex grouped = half_edges_by_low_vertex(mesh);
  const std::vector<int> &start = grouped.start, &by_low = grouped.by_low, &high = grouped.high;
  // Every half-edge's partner: itself on a border, the other face's on an edge of two faces.
  std::vector<int> partner(half_edges, -1);
  for (size_t v = 0; v < mesh.vert.size(); ++v)
    for (int i = start[v]; i < start[v + 1]; ++i) {
      const int h = by_low[size_t(i)];
      if (partner[size_t(h)] >= 0) continue;
      int found = -1, count = 1;
      for (int j = i + 1; j < start[v + 1]; ++j) {
        const int other = by_low[size_t(j)];
        if (high[size_t(other)] != high[size_t(h)]) continue;
        ++count;
        found = other;
      }
      if (count > 2) { // a non-manifold edge: vcglib's fans of faces
        vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
        return;
      }
      partner[size_t(h)] = count == 2 ? found : h;
      if (count == 2) partner[size_t(found)] = h;
    }
  for (size_t h = 0; h < half_edges; ++h) {
    MeshFace &face = mesh.face[h / 3];
    if (face.IsD()) continue;
    const int k = int(h % 3), other = partner[h];
    face.FFp(k) = &mesh.face[size_t(other / 3)];
    face.FFi(k) = char(other % 3);
  }
}

bool is_closed_oriented_connected_manifold(const Mesh &mesh) {
  const size_t face_count = mesh.face.size(), half_edges = 3 * face_count;
  if (face_count < 3) return false;
  for (const MeshFace &face : mesh.face)
    if (face.IsD() || repeats_a_vertex(face)) return false;
  // Half-edges by their starting vertex (a counting sort); the twin of a -> b is the one b -> a.
  std::vector<int> corner(half_edges); // the vertex at corner h % 3 of face h / 3
  for (size_t h = 0; h < half_edges; ++h)
    corner[h] = index_of(mesh, mesh.face[h / 3].cV(int(h % 3)));
  auto from = [&](size_t h) { return corner[h]; };
  auto to = [&](size_t h) { return corner[h - h % 3 + (h % 3 + 1) % 3]; };
  std::vector<int> start(mesh.vert.size() + 1, 0);
  for (size_t h = 0; h < half_edges; ++h)
    ++start[size_t(from(h)) + 1];
  for (size_t v = 0; v < mesh.vert.size(); ++v)
    start[v + 1] += start[v];
  std::vector<int> by_start(half_edges), fill(start.begin(), start.end() - 1);
  for (size_t h = 0; h < half_edges; ++h)
    by_start[size_t(fill[size_t(from(h))]++)] = int(h);
  // Each half-edge a -> b: no other a -> b, exactly one b -> a.
  std::vector<int> twin(half_edges, -1);
  for (size_t h = 0; h < half_edges; ++h) {
    const int a = from(h), b = to(h);
    for (int i = start[size_t(a)]; i < start[size_t(a) + 1]; ++i)
      if (size_t(by_start[size_t(i)]) != h && to(size_t(by_start[size_t(i)])) == b) return false;
    int found = -1;
    for (int i = start[size_t(b)]; i < start[size_t(b) + 1]; ++i)
      if (to(size_t(by_start[size_t(i)])) == a) {
        if (found >= 0) return false;
        found = by_start[size_t(i)];
      }
    if (found < 0) return false;
    twin[h] = found;
  }
  // One fan around every vertex: turning from half-edge a -> b (out of a) to the twin of the
  // half-edge that enters a in the same face reaches every half-edge out of a.
  std::vector<char> turned(half_edges, 0);
  for (size_t v = 0; v < mesh.vert.size(); ++v) {
    const int count = start[v + 1] - start[v];
    if (count == 0) continue; // unreferenced: reported by check_vertices, no matter to topology
    int h = by_start[size_t(start[v])], seen = 0;
    do {
      if (turned[size_t(h)]) return false;
      turned[size_t(h)] = 1;
      ++seen;
      const int entering = 3 * (h / 3) + (h % 3 + 2) % 3;
      h = twin[size_t(entering)];
    } while (h != by_start[size_t(start[v])] && seen <= count);
    if (seen != count) return false;
  }
  // One component: faces reached across their sides from face 0.
  std::vector<char> reached(face_count, 0);
  std::vector<int> stack = {0};
  reached[0] = 1;
  size_t reached_count = 1;
  while (!stack.empty()) {
    const int f = stack.back();
    stack.pop_back();
    for (int k = 0; k < 3; ++k) {
      const int g = twin[size_t(3 * f + k)] / 3;
      if (!reached[size_t(g)]) {
        reached[size_t(g)] = 1;
        ++reached_count;
        stack.push_back(g);
      }
    }
  }
  return reached_count == face_count;
}

void copy_with_face_adjacency(const Mesh &mesh, Mesh &copy) {
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(copy, const_cast<Mesh &>(mesh));
  for (MeshFace &face : copy.face)
    if (!face.IsD() && repeats_a_vertex(face)) vcg::tri::Allocator<Mesh>::DeleteFace(copy, face);
  update_face_adjacency(copy);
}

std::vector<BoundaryLoop> find_boundary_loops(Mesh &mesh) {
  std::vector<BoundaryLoop> loops;
  std::vector<char> visited(mesh.face.size() * 3, 0);
  for (MeshFace &face : mesh.face) {
    if (face.IsD()) continue;
    for (int e = 0; e < 3; ++e) {
      if (!vcg::face::IsBorder(face, e) || visited[3 * index_of(mesh, &face) + e]) continue;
      vcg::face::Pos<MeshFace> start(&face, e), walk = start;
      BoundaryLoop loop;
      loop.first_vertex = index_of(mesh, walk.V());
      do {
        visited[3 * index_of(mesh, walk.F()) + walk.E()] = 1;
        ++loop.length;
        walk.NextB();
      } while (walk != start && loop.length <= 3 * mesh.fn);
      loops.push_back(loop);
    }
  }
  return loops;
}

Topology compute_topology(const Mesh &mesh) {
  Topology topology;
  Mesh work;
  copy_with_face_adjacency(mesh, work);
  topology.faces = work.fn;
  topology.vertices = work.vn - vcg::tri::Clean<Mesh>::CountUnreferencedVertex(work);
  if (topology.faces == 0) return topology;

  int boundary_edges = 0;
  vcg::tri::Clean<Mesh>::CountEdgeNum(work, topology.edges, boundary_edges,
                                      topology.non_manifold_edges);
  if (topology.non_manifold_edges == 0) topology.boundary_loops = find_boundary_loops(work);

  std::vector<std::pair<int, MeshFace *>> components;
  vcg::tri::Clean<Mesh>::ConnectedComponents(work, components);
  for (auto &component : components)
    topology.component_faces.push_back(component.first);

  topology.euler = topology.vertices - topology.edges + topology.faces;
  if (topology.non_manifold_edges == 0) {
    bool oriented = false;
    vcg::tri::Clean<Mesh>::OrientCoherentlyMesh(work, oriented, topology.orientable);
  } else {
    topology.orientable = false;
  }
  const int twice_genus =
      2 * int(components.size()) - topology.euler - int(topology.boundary_loops.size());
  if (components.size() == 1 && topology.non_manifold_edges == 0 && topology.orientable &&
      twice_genus >= 0 && twice_genus % 2 == 0)
    topology.genus = twice_genus / 2;
  return topology;
}

} // namespace meromorph
