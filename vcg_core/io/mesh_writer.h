// Writing the core's mesh to a file, never over an input.
//
// In:  a mesh, an output path (.ply, .obj, .off or .stl), and the paths that must not be written.
// Out: the file, through vcglib's exporters (binary PLY by default, with per-vertex texture
//      coordinates, quality, per-wedge texture coordinates and extra integer and float
//      per-vertex properties when asked for).
// Errors: ArgumentError when the output is one of the protected inputs (same file, even through
//      another path or a link) or has an unsupported extension; WriteError (with the system's
//      reason) when writing fails.
#pragma once

#include <string>
#include <vector>

#include "io/mesh_format.h"
#include "mesh/mesh.h"

namespace meromorph {

// An extra per-vertex integer property written to PLY files (as int, or uchar when `byte`).
struct VertexProperty {
  std::string name;
  std::vector<int> values;
  bool byte = false;
};

// An extra per-vertex float property written to PLY files.
struct FloatVertexProperty {
  std::string name;
  std::vector<float> values;
};

struct WriteOptions {
  bool binary = true;
  bool vertex_texcoords = false;
  bool vertex_quality = false;
  bool wedge_texcoords = false;
  std::vector<VertexProperty> vertex_properties;            // PLY only
  std::vector<FloatVertexProperty> float_vertex_properties; // PLY only
};

// Writes `mesh` to exactly `file` in `format` (a staged temporary path, see staged_outputs.h).
void save_mesh(const Mesh &mesh, MeshFormat format, const std::string &file,
               const WriteOptions &options = {});

// save_mesh through a temporary file beside `path`, moved into place when complete.
void write_mesh(const Mesh &mesh, const std::string &path, const WriteOptions &options = {},
                const std::vector<std::string> &protected_inputs = {});

} // namespace meromorph
