// Which file format a path holds: by its extension, checked against its first bytes.
//
// In:  a file path.
// Out: `MeshFormat` (PLY, OBJ, OFF, STL). Throws ArgumentError for a missing or unreadable file or
//      an extension meromorph does not read, and InputError for an empty file or content that does
//      not match the extension (for example a binary file named .off), saying what it looks like.
#pragma once

#include <string>

namespace meromorph {

enum class MeshFormat { ply, obj, off, stl };

const char *format_name(MeshFormat format);      // "PLY"
const char *format_extension(MeshFormat format); // ".ply"

// The format that the extension of `path` names; throws ArgumentError for any other extension.
MeshFormat format_from_extension(const std::string &path);

// The format an output path asks for, by its extension; throws ArgumentError for a folder or any
// other extension, in words about writing.
MeshFormat output_format(const std::string &path);

// The format of an existing file, by extension, after checking that its content agrees.
MeshFormat detect_format(const std::string &path);

} // namespace meromorph
