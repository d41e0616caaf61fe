// Plain arrays <-> the core's mesh.
//
// In:  `MeshArrays`: vertex positions and triangles as 0-based vertex indices (every index must be
//      in range: the readers check it and name the file line, adapters check it and name the face).
// Out: a vcglib `Mesh` with the same vertices and faces in the same order, and back again.
//      The order is kept, so every index a later message names is the input's own index.
#pragma once

#include <array>
#include <vector>

#include "mesh/mesh.h"

namespace meromorph {

struct MeshArrays {
  std::vector<Point3> positions;
  std::vector<std::array<int, 3>> triangles;
  // Readers: per triangle, the file's face it was split from (empty when no face was split).
  std::vector<int> triangle_face;
};

// Replaces `mesh` by the vertices and triangles of `arrays`. Throws InputError for an index that
// is out of range (naming the face).
void mesh_from_arrays(const MeshArrays &arrays, Mesh &mesh);

// The live (not deleted) vertices and faces of `mesh`, renumbered densely in storage order.
MeshArrays arrays_from_mesh(const Mesh &mesh);

} // namespace meromorph
