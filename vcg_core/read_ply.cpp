// vcglib's PLY importer needs the mesh types and <cstring> before it.
#include "format_readers.h"

#include <cstring>
#include <filesystem>
#include <string>

#include <wrap/io_trimesh/import_ply.h>

#include "errors.h"

namespace meromorph {
namespace {

// vcglib's messages, in words that say what is wrong with the file.
std::string explain_ply_error(int code) {
  using Importer = vcg::tri::io::ImporterPLY<Mesh>;
  switch (code) {
  case vcg::ply::E_CANTOPEN:
    return "cannot be opened";
  case vcg::ply::E_NOTHEADER:
    return "has no PLY header";
  case vcg::ply::E_UNESPECTEDEOF:
    return "ends inside its header (truncated?)";
  case vcg::ply::E_NOFORMAT:
    return "has no 'format' line in its header";
  case vcg::ply::E_SYNTAX:
    return "has a syntax error in its header";
  case vcg::tri::io::PlyInfo::E_NO_VERTEX:
    return "has no vertex element with x, y, z";
  case vcg::tri::io::PlyInfo::E_SHORTFILE:
    return "ends before all the vertices and faces its header announces (truncated, or the "
           "header's counts are wrong)";
  case vcg::tri::io::PlyInfo::E_BAD_VERT_INDEX:
    return "has a face that refers to a vertex index beyond the vertex count";
  default:
    return std::string("cannot be read (") + Importer::ErrorMsg(code) + ")";
  }
}

// The header's element counts must fit in the file: each value takes at least one byte. Catches
// headers that lie about their counts before anything is allocated.
void check_header_counts(const std::string &path) {
  vcg::ply::PlyFile header;
  if (header.Open(path.c_str(), vcg::ply::PlyFile::MODE_READ) != 0) return; // the importer says why
  std::error_code error;
  const double file_size = double(std::filesystem::file_size(path, error));
  double minimum = 0;
  for (const vcg::ply::PlyElement &element : header.elements) {
    if (element.number < 0)
      throw InputError(path + ": the PLY header gives element '" + element.name +
                       "' a negative or too large count");
    minimum += double(element.props.size()) * double(element.number);
  }
  if (minimum > file_size)
    throw InputError(path + ": the PLY header announces more vertices and faces than a file of " +
                     std::to_string(std::uintmax_t(file_size)) +
                     " bytes can hold (truncated, or a wrong header)");
}

} // namespace

void read_ply(const std::string &path, Mesh &mesh, std::vector<std::string> &notes) {
  using Importer = vcg::tri::io::ImporterPLY<Mesh>;
  check_header_counts(path);
  int mask = 0;
  mesh.Clear();
  const int code = Importer::Open(mesh, path.c_str(), mask);
  if (code == vcg::tri::io::PlyInfo::E_NO_FACE) {
    notes.push_back("the PLY file has no face element (a point cloud?)");
  } else if (code != vcg::ply::E_NOERROR) {
    mesh.Clear();
    throw InputError(path + ": the PLY file " + explain_ply_error(code));
  }
}

} // namespace meromorph
