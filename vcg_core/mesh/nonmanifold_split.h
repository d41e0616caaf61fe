// Non-manifold spots taken apart, so every vertex has one fan of faces and every edge at most two.
//
// In:  a mesh as read (it may have edges shared by more than two faces and vertices where pieces
//      of surface touch).
// Out: `split`, the same faces in the same order whose corners point at the vertices of the split
//      mesh: the input's vertices first, in order (each keeps the fan of its first face), then one
//      copy per further fan of a non-manifold vertex, at the same position. Along an edge with
//      more than two faces, each face is glued to the face next to it around the edge on the side
//      its back faces, when that one faces back the other way (two solids touching along an edge
//      become two closed solids); faces left without a partner there get a boundary edge (a hole).
//      `NonmanifoldSplit` says for every vertex of the split mesh its input vertex, which input
//      vertices were split and which edges were taken apart.
#pragma once

#include <array>
#include <vector>

#include "mesh/mesh.h"

namespace meromorph {

struct NonmanifoldSplit {
  std::vector<int> source_vertex;              // per vertex of the split mesh: the input vertex
  std::vector<int> split_vertices;             // input vertices that got copies
  std::vector<std::array<int, 2>> split_edges; // input edges with more than two faces
  int added_vertices = 0;
  bool changed() const { return added_vertices > 0; }
};

NonmanifoldSplit split_nonmanifold(const Mesh &input, Mesh &split);

} // namespace meromorph
