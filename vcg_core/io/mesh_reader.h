// Reading a mesh file of any supported format into the core's mesh.
//
// In:  a path to a .ply, .obj, .off or .stl file.
// Out: `mesh` holds the file's vertices and triangles in file order (0-based indices; polygons are
//      triangulated after their predecessors), and the returned `MeshSource` says the format and
//      what the reader had to do (with `vertex_values`, a PLY file's other per-vertex values).
//      Nothing is validated here (see validation.h).
// Errors: ArgumentError (no such file, unsupported extension), InputError (empty, truncated or
//      malformed file, content that does not match the extension), with the path and line.
#pragma once

#include <string>
#include <vector>

#include "common/progress.h"
#include "io/mesh_format.h"
#include "mesh/mesh.h"
#include "mesh/mesh_from_arrays.h"

namespace meromorph {

struct MeshSource {
  std::string path;
  MeshFormat format = MeshFormat::ply;
  std::vector<std::string> notes;
  // Per triangle, the file's face it was split from, when polygons were triangulated (else empty).
  std::vector<int> triangle_face;
  // With `vertex_values`: the values the file carries per vertex beside the position (PLY).
  std::vector<VertexValues> vertex_values;
};

MeshSource read_mesh(const std::string &path, Mesh &mesh, const Progress &progress = {},
                     bool vertex_values = false);

} // namespace meromorph
