// Plain arrays <-> the core's mesh.
//
// In:  `MeshArrays`: vertex positions and triangles as 0-based vertex indices (every index must be
//      in range: the readers check it and name the file line, adapters check it and name the face).
// Out: a vcglib `Mesh` with the same vertices and faces in the same order, and back again.
//      The order is kept, so every index a later message names is the input's own index.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace meromorph {

// A per-vertex value a file carries beside the position (PLY: a scalar property of the vertex
// element), read only when asked for.
struct VertexValues {
  std::string name;
  bool integer = false; // an integer type in the file
  bool byte = false;    // a one-byte type (char, uchar: colours)
  std::vector<double> values;
};

struct MeshArrays {
  std::vector<Point3> positions;
  std::vector<VertexValues> vertex_values; // PLY, when asked for: every scalar but x, y, z
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
