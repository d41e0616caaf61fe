#include "mesh/mesh_edges.h"

#include <map>
#include <set>

#include <algorithm>
#include <queue>
#include <unordered_map>

#include "common/errors.h"

namespace meromorph {

MeshEdges build_mesh_edges(const Mesh &mesh) {
  MeshEdges edges;
  const int face_count = int(mesh.face.size());
  edges.face_edges.assign(face_count, {-1, -1, -1});
  edges.face_signs.assign(face_count, {0, 0, 0});
  std::unordered_map<std::uint64_t, int> edge_of;
  edge_of.reserve(size_t(face_count) * 2);
  auto key = [](int a, int b) {
    return (std::uint64_t(std::min(a, b)) << 32) | std::uint32_t(std::max(a, b));
  };
  for (int f = 0; f < face_count; ++f) {
    const MeshFace &face = mesh.face[f];
    for (int k = 0; k < 3; ++k) {
      const int from = index_of(mesh, face.cV(k)), to = index_of(mesh, face.cV((k + 1) % 3));
      auto [it, inserted] = edge_of.emplace(key(from, to), edges.edge_count());
      if (inserted) {
        edges.vertices.push_back({from, to});
        edges.faces.push_back({f, -1});
        edges.face_edges[f][k] = it->second;
        edges.face_signs[f][k] = 1;
      } else {
        const int e = it->second;
        if (edges.vertices[e][0] != to || edges.faces[e][1] != -1)
          throw InputError("edge " + std::to_string(from) + "-" + std::to_string(to) +
                           " is not shared by exactly two consistently oriented faces");
        edges.faces[e][1] = f;
        edges.face_edges[f][k] = e;
        edges.face_signs[f][k] = -1;
      }
    }
  }
  for (int e = 0; e < edges.edge_count(); ++e)
    if (edges.faces[e][1] < 0)
      throw InputError("edge " + std::to_string(edges.vertices[e][0]) + "-" +
                       std::to_string(edges.vertices[e][1]) + " lies on a boundary");
  return edges;
}

std::vector<std::vector<int>> edges_at_vertices(const MeshEdges &edges, int vertex_count) {
  std::vector<std::vector<int>> incident(vertex_count);
  for (int e = 0; e < edges.edge_count(); ++e)
    for (int end : edges.vertices[e])
      incident[end].push_back(e);
  return incident;
}

FaceIncidence face_incidence(const Mesh &mesh) {
  FaceIncidence in;
  in.faces_of_vertex.resize(mesh.vert.size());
  in.corners.resize(mesh.face.size());
  for (size_t f = 0; f < mesh.face.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      in.corners[f][k] = index_of(mesh, mesh.face[f].cV(k));
      in.faces_of_vertex[in.corners[f][k]].push_back(int(f));
    }
  return in;
}

std::map<int, int> ring_distances(const FaceIncidence &in, const std::vector<int> &sources,
                                  int radius) {
  std::map<int, int> distance;
  std::queue<int> queue;
  for (int v : sources) {
    distance[v] = 0;
    queue.push(v);
  }
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop();
    if (distance[v] >= radius) continue;
    for (int f : in.faces_of_vertex[v])
      for (int w : in.corners[f])
        if (distance.emplace(w, distance[v] + 1).second) queue.push(w);
  }
  return distance;
}

BoundaryLoops chain_boundary(const std::vector<std::array<int, 3>> &triangles) {
  std::set<std::pair<int, int>> walked;
  for (const auto &t : triangles)
    for (int k = 0; k < 3; ++k)
      walked.insert({t[size_t(k)], t[size_t((k + 1) % 3)]});
  BoundaryLoops out;
  std::map<int, int> next; // b of the boundary half-edge that starts at a
  for (const auto &[a, b] : walked)
    if (!walked.count({b, a}) && !next.insert({a, b}).second) {
      out.pinched_vertex = a;
      return out;
    }
  std::set<int> used;
  for (const auto &[start, ignored] : next) {
    if (used.count(start)) continue;
    std::vector<int> loop;
    for (int v = start; used.insert(v).second; v = next.at(v)) {
      loop.push_back(v);
      if (!next.count(next.at(v))) break;
    }
    out.loops.push_back(std::move(loop));
  }
  return out;
}

} // namespace meromorph
