#include "mesh/topology.h"

#include <algorithm>

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

void copy_with_face_adjacency(const Mesh &mesh, Mesh &copy) {
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(copy, const_cast<Mesh &>(mesh));
  for (MeshFace &face : copy.face)
    if (!face.IsD() && repeats_a_vertex(face)) vcg::tri::Allocator<Mesh>::DeleteFace(copy, face);
  vcg::tri::UpdateTopology<Mesh>::FaceFace(copy);
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
