#include "mesh/topology.h"

#include <algorithm>

#include "common/parallel_for.h"
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

namespace {

// Per live half-edge h = 3 f + k its partner: itself on a border, the other face's half-edge on
// an edge of two faces; empty when some edge has more than two faces. Deleted faces' half-edges
// get -1. The half-edges of each low vertex are paired over the cores.
std::vector<int> half_edge_partners(const Mesh &mesh) {
  const size_t half_edges = 3 * mesh.face.size();
  const HalfEdgesByLowVertex grouped = half_edges_by_low_vertex(mesh);
  const std::vector<int> &start = grouped.start, &by_low = grouped.by_low, &high = grouped.high;
  std::vector<int> partner(half_edges, -1);
  std::vector<char> non_manifold(mesh.vert.size(), 0);
  parallel_for(mesh.vert.size(), [&](size_t v) {
    // The half-edges on the same two vertices are consecutive (half_edges_by_low_vertex).
    for (int i = start[v]; i < start[v + 1];) {
      const int h = by_low[size_t(i)];
      int end = i + 1;
      while (end < start[v + 1] && high[size_t(by_low[size_t(end)])] == high[size_t(h)])
        ++end;
      if (end - i > 2) { // a non-manifold edge
        non_manifold[v] = 1;
        return;
      }
      const int other = by_low[size_t(end - 1)];
      partner[size_t(h)] = other;
      partner[size_t(other)] = h;
      i = end;
    }
  });
  if (std::find(non_manifold.begin(), non_manifold.end(), 1) != non_manifold.end()) return {};
  return partner;
}

} // namespace

void update_face_adjacency(Mesh &mesh) {
  const std::vector<int> partner = half_edge_partners(mesh);
  if (partner.empty()) { // a non-manifold edge: vcglib's fans of faces
    vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
    return;
  }
  for (size_t h = 0; h < partner.size(); ++h) {
    MeshFace &face = mesh.face[h / 3];
    if (face.IsD()) continue;
    const int k = int(h % 3), other = partner[h];
    face.FFp(k) = &mesh.face[size_t(other / 3)];
    face.FFi(k) = char(other % 3);
  }
}

bool is_closed_oriented_connected_manifold(const Mesh &mesh) {
  const size_t face_count = mesh.face.size();
  if (face_count < 3) return false;
  for (const MeshFace &face : mesh.face)
    if (face.IsD() || repeats_a_vertex(face)) return false;
  // Every side shared with exactly one other face, which runs it the other way: the twin.
  const std::vector<int> twin = half_edge_partners(mesh);
  if (twin.empty()) return false;
  auto vertex_at = [&](size_t h) { return mesh.face[h / 3].cV(int(h % 3)); };
  const int mismatched = chunked_sum(twin.size(), 0, [&](size_t begin, size_t end) {
    int count = 0;
    for (size_t h = begin; h < end; ++h) {
      const size_t t = size_t(twin[h]);
      count += t == h || vertex_at(t) != vertex_at(3 * (h / 3) + (h % 3 + 1) % 3);
    }
    return count;
  });
  if (mismatched) return false;
  std::vector<int> out_of(mesh.vert.size(), 0); // half-edges leaving each vertex
  std::vector<int> first_out(mesh.vert.size(), -1);
  for (size_t h = 0; h < twin.size(); ++h) {
    const size_t v = size_t(index_of(mesh, vertex_at(h)));
    ++out_of[v];
    if (first_out[v] < 0) first_out[v] = int(h);
  }
  // One fan around every vertex: turning from a half-edge out of a vertex to the twin of the
  // half-edge that enters it in the same face goes round all the half-edges out of it (each
  // vertex's turns visit only its own half-edges: over the cores).
  std::vector<char> pinched(mesh.vert.size(), 0);
  parallel_for(mesh.vert.size(), [&](size_t v) {
    if (first_out[v] < 0) return;
    const size_t first = size_t(first_out[v]);
    int seen = 0;
    size_t h = first;
    do {
      ++seen;
      h = size_t(twin[3 * (h / 3) + (h % 3 + 2) % 3]);
    } while (h != first && seen <= out_of[v]);
    pinched[v] = seen != out_of[v];
  });
  if (std::find(pinched.begin(), pinched.end(), 1) != pinched.end()) return false;
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
