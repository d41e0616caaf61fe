#include "mesh/mesh_edges.h"

#include <map>
#include <set>

#include <algorithm>
#include <queue>

#include "common/errors.h"

namespace meromorph {

namespace {

// Per half-edge h = 3 f + k (side k of face f), the first half-edge on the same two vertices:
// the half-edges grouped on their lower vertex, then matched within each vertex's few.
std::vector<int> first_half_edge_on_same_vertices(const Mesh &mesh) {
  const size_t half_edges = 3 * mesh.face.size();
  const HalfEdgesByLowVertex grouped = half_edges_by_low_vertex(mesh);
  const std::vector<int> &start = grouped.start, &by_low = grouped.by_low, &high = grouped.high;
  std::vector<int> first(half_edges);
  for (size_t v = 0; v < mesh.vert.size(); ++v)
    for (int i = start[v]; i < start[v + 1]; ++i) {
      const int h = by_low[size_t(i)];
      first[size_t(h)] = h;
      for (int j = start[v]; j < i; ++j)
        if (high[size_t(by_low[size_t(j)])] == high[size_t(h)]) {
          first[size_t(h)] = first[size_t(by_low[size_t(j)])];
          break;
        }
    }
  return first;
}

} // namespace

HalfEdgesByLowVertex half_edges_by_low_vertex(const Mesh &mesh) {
  const size_t half_edges = 3 * mesh.face.size();
  HalfEdgesByLowVertex out;
  out.low.assign(half_edges, -1);
  out.high.assign(half_edges, -1);
  out.start.assign(mesh.vert.size() + 1, 0);
  for (size_t h = 0; h < half_edges; ++h) {
    const MeshFace &face = mesh.face[h / 3];
    if (face.IsD()) continue;
    const int k = int(h % 3);
    const int a = index_of(mesh, face.cV(k)), b = index_of(mesh, face.cV((k + 1) % 3));
    out.low[h] = std::min(a, b);
    out.high[h] = std::max(a, b);
    ++out.start[size_t(out.low[h]) + 1];
  }
  for (size_t v = 0; v < mesh.vert.size(); ++v)
    out.start[v + 1] += out.start[v];
  out.by_low.resize(size_t(out.start.back()));
  std::vector<int> fill(out.start.begin(), out.start.end() - 1);
  for (size_t h = 0; h < half_edges; ++h) // in increasing h within each vertex
    if (out.low[h] >= 0) out.by_low[size_t(fill[size_t(out.low[h])]++)] = int(h);
  return out;
}

MeshEdges build_mesh_edges(const Mesh &mesh) {
  MeshEdges edges;
  const int face_count = int(mesh.face.size());
  edges.face_edges.assign(face_count, {-1, -1, -1});
  edges.face_signs.assign(face_count, {0, 0, 0});
  edges.vertices.reserve(size_t(face_count) * 3 / 2);
  edges.faces.reserve(size_t(face_count) * 3 / 2);
  // Edges numbered in the order the faces first reach them.
  const std::vector<int> first = first_half_edge_on_same_vertices(mesh);
  for (int f = 0; f < face_count; ++f) {
    const MeshFace &face = mesh.face[f];
    for (int k = 0; k < 3; ++k) {
      const int from = index_of(mesh, face.cV(k)), to = index_of(mesh, face.cV((k + 1) % 3));
      const int h = 3 * f + k, earlier = first[size_t(h)];
      if (earlier == h) {
        edges.face_edges[f][k] = edges.edge_count();
        edges.face_signs[f][k] = 1;
        edges.vertices.push_back({from, to});
        edges.faces.push_back({f, -1});
      } else {
        const int e = edges.face_edges[size_t(earlier / 3)][size_t(earlier % 3)];
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

IndexLists edges_at_vertices(const MeshEdges &edges, int vertex_count) {
  return IndexLists::grouped(size_t(vertex_count), [&](const auto &emit) {
    for (int e = 0; e < edges.edge_count(); ++e)
      for (int end : edges.vertices[size_t(e)])
        emit(end, e);
  });
}

FaceIncidence face_incidence(const Mesh &mesh) {
  FaceIncidence in;
  in.corners.resize(mesh.face.size());
  for (size_t f = 0; f < mesh.face.size(); ++f)
    for (int k = 0; k < 3; ++k)
      in.corners[f][k] = index_of(mesh, mesh.face[f].cV(k));
  in.faces_of_vertex = IndexLists::grouped(mesh.vert.size(), [&](const auto &emit) {
    for (size_t f = 0; f < in.corners.size(); ++f)
      for (int v : in.corners[f])
        emit(v, int(f));
  });
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
