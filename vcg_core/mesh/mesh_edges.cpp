#include "mesh/mesh_edges.h"

#include <algorithm>
#include <climits>
#include <stdexcept>

#include "common/errors.h"
#include "common/thread_scratch.h"

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
      const bool same_as_previous =
          i > start[v] && high[size_t(by_low[size_t(i - 1)])] == high[size_t(h)];
      first[size_t(h)] = same_as_previous ? first[size_t(by_low[size_t(i - 1)])] : h;
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
  // First by the higher vertex (stable in h), then by the lower one (stable): ordered by
  // (low, high, h).
  std::vector<int> high_start(mesh.vert.size() + 1, 0);
  for (size_t h = 0; h < half_edges; ++h)
    if (out.low[h] >= 0) ++high_start[size_t(out.high[h]) + 1];
  for (size_t v = 0; v < mesh.vert.size(); ++v)
    high_start[v + 1] += high_start[v];
  std::vector<int> by_high(size_t(high_start.back()));
  for (size_t h = 0; h < half_edges; ++h)
    if (out.low[h] >= 0) by_high[size_t(high_start[size_t(out.high[h])]++)] = int(h);
  high_start = {};
  out.by_low.resize(by_high.size());
  std::vector<int> fill(out.start.begin(), out.start.end() - 1);
  for (int h : by_high)
    out.by_low[size_t(fill[size_t(out.low[size_t(h)])]++)] = h;
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

BoundaryLoops chain_boundary(const std::vector<std::array<int, 3>> &triangles) {
  std::vector<std::pair<int, int>> walked;
  walked.reserve(3 * triangles.size());
  for (const auto &t : triangles)
    for (int k = 0; k < 3; ++k)
      walked.push_back({t[size_t(k)], t[size_t((k + 1) % 3)]});
  return chain_boundary(std::move(walked));
}

BoundaryLoops chain_boundary(std::vector<std::pair<int, int>> walked) {
  // The half-edges walked, sorted (each once), and the boundary ones (no reverse walked) as
  // (a, b) sorted on a: at most one per start vertex, else a pinch.
  std::sort(walked.begin(), walked.end());
  walked.erase(std::unique(walked.begin(), walked.end()), walked.end());
  BoundaryLoops out;
  std::vector<std::pair<int, int>> next; // b of the boundary half-edge that starts at a
  for (const auto &[a, b] : walked) {
    if (std::binary_search(walked.begin(), walked.end(), std::pair<int, int>{b, a})) continue;
    if (!next.empty() && next.back().first == a) {
      out.pinched_vertex = a;
      return out;
    }
    next.push_back({a, b});
  }
  // The position in `next` of the half-edge starting at v, -1 if none.
  auto position = [&](int v) {
    const auto at = std::lower_bound(next.begin(), next.end(), std::pair<int, int>{v, INT_MIN});
    return at != next.end() && at->first == v ? int(at - next.begin()) : -1;
  };
  std::vector<char> used(next.size(), 0);
  for (size_t start = 0; start < next.size(); ++start) {
    if (used[start]) continue;
    std::vector<int> loop;
    for (int i = int(start); i >= 0 && !used[size_t(i)]; i = position(next[size_t(i)].second)) {
      used[size_t(i)] = 1;
      loop.push_back(next[size_t(i)].first);
    }
    out.loops.push_back(std::move(loop));
  }
  return out;
}

std::vector<RingDistances::Entry>::const_iterator RingDistances::find(int vertex) const {
  const auto at = std::lower_bound(by_vertex_.begin(), by_vertex_.end(), Entry{vertex, INT_MIN});
  return at != by_vertex_.end() && at->first == vertex ? at : by_vertex_.end();
}

int RingDistances::at(int vertex) const {
  const auto found = find(vertex);
  if (found == end()) throw std::out_of_range("ring_distances: vertex beyond the radius");
  return found->second;
}

RingDistances ring_distances(const FaceIncidence &in, const std::vector<int> &sources, int radius) {
  // Per vertex of the mesh, whether the search has reached it: set while a search runs, cleared
  // after (one array per thread, kept between searches: a search touches only its region).
  struct Reached; // (the scratch's tag: common/thread_scratch.h)
  std::vector<char> &reached = thread_scratch<Reached, std::vector<char>>();
  if (reached.size() < in.faces_of_vertex.size()) reached.assign(in.faces_of_vertex.size(), 0);
  std::vector<RingDistances::Entry> found; // breadth first: its own queue
  for (int v : sources)
    if (!reached[size_t(v)]) {
      reached[size_t(v)] = 1;
      found.push_back({v, 0});
    }
  for (size_t i = 0; i < found.size(); ++i) {
    const auto [v, rings] = found[i];
    if (rings >= radius) continue;
    for (int f : in.faces_of_vertex[size_t(v)])
      for (int w : in.corners[size_t(f)])
        if (!reached[size_t(w)]) {
          reached[size_t(w)] = 1;
          found.push_back({w, rings + 1});
        }
  }
  for (const auto &entry : found)
    reached[size_t(entry.first)] = 0;
  std::sort(found.begin(), found.end());
  return RingDistances(std::move(found));
}

} // namespace meromorph
