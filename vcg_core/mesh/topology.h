// Topology of a triangle mesh: counts, boundary loops, components, Euler characteristic, genus.
//
// In:  a mesh (faces that repeat a vertex are left out of every count: they have no proper edges).
// Out: `Topology`: V (vertices used by faces), E, F, the boundary loops (each with a vertex on it
//      and its length in edges), the connected components (through shared edges), chi = V - E + F
//      and the genus g = (2 - chi - b) / 2 of the surface when it is one connected,
//      edge-manifold, orientable piece (absent otherwise).
#pragma once

#include <optional>
#include <vector>

#include "mesh/mesh.h"

namespace meromorph {

struct BoundaryLoop {
  int first_vertex = -1;
  int length = 0; // edges
};

// The boundary loops of `mesh`. Needs face-face adjacency and no non-manifold edge.
std::vector<BoundaryLoop> find_boundary_loops(Mesh &mesh);

// Per vertex: 1 when it is on an edge that only one face has (an edge of a hole). Faces that
// repeat a vertex are left out. Works on any mesh.
std::vector<char> boundary_vertices(const Mesh &mesh);

// A copy of `mesh` without the faces that repeat a vertex, with face-face adjacency; vertex and
// face indices stay those of `mesh` (deleted faces keep their slots).
void copy_with_face_adjacency(const Mesh &mesh, Mesh &copy);

// Whether the mesh is one closed, consistently oriented, manifold surface (every side shared with
// exactly one face that runs it the other way, one fan of faces around every vertex, one
// component; no face repeating a vertex): linear time, no copy. Validation's quick path.
bool is_closed_oriented_connected_manifold(const Mesh &mesh);

// Face-face adjacency as vcglib's UpdateTopology::FaceFace sets it (deleted faces left out), in
// linear time where every edge has one or two faces; vcglib's own where an edge has more.
void update_face_adjacency(Mesh &mesh);

struct Topology {
  int vertices = 0;
  int edges = 0;
  int faces = 0;
  int non_manifold_edges = 0;
  std::vector<BoundaryLoop> boundary_loops;
  std::vector<int> component_faces; // faces per connected component
  int euler = 0;
  std::optional<int> genus;
  bool orientable = true;

  bool closed_manifold() const {
    return boundary_loops.empty() && non_manifold_edges == 0 && component_faces.size() == 1;
  }
};

Topology compute_topology(const Mesh &mesh);

} // namespace meromorph
