#include "io/mesh_reader.h"

#include <fstream>
#include <sstream>

#include "common/errors.h"
#include "io/format_readers.h"
#include "io/text_lines.h"

namespace meromorph {

namespace {

// The whole file as a string; throws ArgumentError if it cannot be read.
std::string read_whole_file(const std::string &path) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw ArgumentError(path + ": cannot be opened for reading");
  std::ostringstream content;
  content << stream.rdbuf();
  return content.str();
}

} // namespace

MeshSource read_mesh(const std::string &path, Mesh &mesh, const Progress &progress,
                     bool vertex_values) {
  MeshSource source;
  source.path = path;
  source.format = detect_format(path);
  progress.report(0.0, "reading " + path);
  {
    const std::string content = read_whole_file(path);
    MeshArrays arrays;
    switch (source.format) {
    case MeshFormat::off:
      arrays = read_off(path, content, source.notes);
      break;
    case MeshFormat::obj:
      arrays = read_obj(path, content, source.notes);
      break;
    case MeshFormat::stl:
      arrays = read_stl(path, content, source.notes);
      break;
    case MeshFormat::ply:
      arrays = read_ply(path, content, source.notes, vertex_values);
      break;
    }
    mesh_from_arrays(arrays, mesh);
    source.triangle_face = std::move(arrays.triangle_face);
    source.vertex_values = std::move(arrays.vertex_values);
  }
  vcg::tri::UpdateBounding<Mesh>::Box(mesh);
  progress.report(1.0, "reading " + path);
  return source;
}

} // namespace meromorph
