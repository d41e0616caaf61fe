// Helpers for the tests: test data paths, a temporary folder, running the CLI.
//
// In:  file names under tests/data, text to write, command-line arguments.
// Out: absolute paths; a folder removed at the end of the test; the CLI's exit code and output.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace meromorph::test {

std::string data_path(const std::string &name);

class TempDir {
public:
  TempDir();
  ~TempDir();
  std::string path(const std::string &name) const { return root_ + "/" + name; }
  std::string write(const std::string &name, const std::string &content) const;

private:
  std::string root_;
};

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// The bytes of the file at `path` (empty if it cannot be read).
std::string file_bytes(const std::string &path);

// Runs the meromorph CLI with `arguments` (each shell-quoted).
RunResult run_cli(const std::vector<std::string> &arguments);

// Reads `path` into `mesh`, failing the test on any error.
void load(const std::string &path, Mesh &mesh);
// A well-formed PLY file (written by MeshLab or by meromorph) through vcglib's importer, which,
// unlike meromorph's reader, also loads per-vertex texture coordinates, quality and flags
// (selection).
void load_ply_attributes(const std::string &path, Mesh &mesh);

// An OFF file with these vertices and triangles.
std::string off_text(const std::vector<std::array<double, 3>> &positions,
                     const std::vector<std::array<int, 3>> &triangles);

// The vertex positions and triangles of a mesh file (read as `load` does).
void arrays_of(const std::string &file, std::vector<std::array<double, 3>> &positions,
               std::vector<std::array<int, 3>> &triangles);

// Two unit cubes (12 triangles each, counter-clockwise from outside) sharing the edge
// x = y = 1: a non-manifold edge of four faces, as OFF text.
std::string cubes_sharing_an_edge_off();

} // namespace meromorph::test
