// One reader per file format, each strict: a malformed file is refused with its path and line,
// never half-read.
//
// In:  the file path (and, for the text formats, its whole content).
// Out: `MeshArrays` (polygons triangulated, indices checked). Notes on what the reader did
// (triangulated polygons, welded STL corners)
//      go into `notes`. Errors: InputError naming the file, the line and what is wrong.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/mesh_from_arrays.h"

namespace meromorph {

// OFF and its variants (COFF, NOFF, ...): comment lines anywhere, colours and extra values ignored.
MeshArrays read_off(const std::string &path, const std::string &text,
                    std::vector<std::string> &notes);

// Wavefront OBJ: `v` and `f` records (1-based or negative indices, v/vt/vn forms); everything else
// (texture coordinates, normals, groups, materials, lines) is ignored.
MeshArrays read_obj(const std::string &path, const std::string &text,
                    std::vector<std::string> &notes);

// STL, ASCII or binary. STL stores every triangle's corners separately; the reader welds corners
// at exactly the same position into one vertex (the only connectivity STL has) and says so.
MeshArrays read_stl(const std::string &path, const std::string &bytes,
                    std::vector<std::string> &notes);

// PLY, ASCII and binary (little and big endian): the `vertex` element's x, y, z and the `face`
// element's `vertex_indices` list (any integer count and index types; polygons triangulated);
// every other element and property is read past by its declared type (with `vertex_values`, the
// vertex element's other scalar properties are kept in MeshArrays::vertex_values). Every count,
// list length and index is checked; errors name the header or data line (ASCII) or the byte
// offset (binary).
MeshArrays read_ply(const std::string &path, const std::string &bytes,
                    std::vector<std::string> &notes, bool vertex_values = false);

} // namespace meromorph
