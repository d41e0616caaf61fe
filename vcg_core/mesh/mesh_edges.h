// Oriented edges of a closed, oriented, edge-manifold triangle mesh, for 1-forms.
//
// In:  a compact mesh that validation accepted (closed, oriented, manifold).
// Out: `MeshEdges`: every edge once, oriented from `vertices[e][0]` to `vertices[e][1]`; its left
//      face (which traverses it in that direction) and right face; for every face its three edges
//      (edge k joins corners k and k+1) and the sign (+1 when the face traverses the edge in the
//      edge's direction). A 1-form is a vector of per-edge values in the edges' directions.
//      Also, for any compact mesh, the incidences the map stages walk: edges at each vertex, and
//      faces at each vertex with every face's three vertices.
#pragma once

#include <array>
#include <map>
#include <utility>
#include <vector>

#include "mesh/index_lists.h"
#include "mesh/mesh.h"

namespace meromorph {

struct MeshEdges {
  std::vector<std::array<int, 2>> vertices;           // per edge: from, to
  std::vector<std::array<int, 2>> faces;              // per edge: left, right
  std::vector<std::array<int, 3>> face_edges;         // per face: edge of side k (corner k -> k+1)
  std::vector<std::array<signed char, 3>> face_signs; // per face: +1 / -1 (one byte each)

  int edge_count() const { return int(vertices.size()); }
};

MeshEdges build_mesh_edges(const Mesh &mesh);

// The half-edges h = 3 f + k (side k of face f, deleted faces left out: low = -1) grouped by
// their lower vertex in linear time (two counting sorts): those of vertex v are
// by_low[start[v] .. start[v + 1]), ordered by their other vertex `high`, then by h; so the
// half-edges on the same two vertices are consecutive, whatever the vertex's valence.
struct HalfEdgesByLowVertex {
  std::vector<int> low, high, start, by_low;
};
HalfEdgesByLowVertex half_edges_by_low_vertex(const Mesh &mesh);

// For each vertex, the edges that end at it.
IndexLists edges_at_vertices(const MeshEdges &edges, int vertex_count);

struct FaceIncidence {
  std::vector<std::array<int, 3>> corners; // per face: its three vertices
  IndexLists faces_of_vertex;              // per vertex: the faces around it
};

FaceIncidence face_incidence(const Mesh &mesh);

// The boundary of a set of oriented triangles: its half-edges a -> b whose reverse no triangle
// walks, chained into closed loops in the triangles' walking direction. Where two boundary
// half-edges start at one vertex (holes touching there), no loops and that vertex.
struct BoundaryLoops {
  std::vector<std::vector<int>> loops;
  int pinched_vertex = -1;
};
BoundaryLoops chain_boundary(const std::vector<std::array<int, 3>> &triangles);
// The same from the triangles' half-edges (a, b), in any order: a caller that knows which
// half-edges can be on the boundary passes those (and their reverses) alone.
BoundaryLoops chain_boundary(std::vector<std::pair<int, int>> walked);

// The ring distance from `sources` of every vertex at most `radius` rings away: (vertex, rings)
// in the order of the vertices, looked up by binary search (the regions are a few hundred
// vertices; a std::map of them was a tenth of the branch snapping's time).
class RingDistances {
public:
  using Entry = std::pair<int, int>;
  explicit RingDistances(std::vector<Entry> by_vertex) : by_vertex_(std::move(by_vertex)) {}
  std::vector<Entry>::const_iterator begin() const { return by_vertex_.begin(); }
  std::vector<Entry>::const_iterator end() const { return by_vertex_.end(); }
  size_t size() const { return by_vertex_.size(); }
  // The entry of `vertex`, end() where it is farther than the radius.
  std::vector<Entry>::const_iterator find(int vertex) const;
  bool count(int vertex) const { return find(vertex) != end(); }
  // Its rings; throws std::out_of_range where it is farther (as std::map::at).
  int at(int vertex) const;

private:
  std::vector<Entry> by_vertex_;
};

RingDistances ring_distances(const FaceIncidence &in, const std::vector<int> &sources, int radius);

} // namespace meromorph
