#include "test_support.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <sys/wait.h>

#include <gtest/gtest.h>

#include <cstring>

#include <wrap/io_trimesh/import_ply.h>

#include "io/mesh_reader.h"

namespace meromorph::test {

std::string data_path(const std::string &name) {
  return std::string(MEROMORPH_TEST_DATA) + "/" + name;
}

TempDir::TempDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "meromorph-test-XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot make a temporary folder");
  root_ = pattern;
}

TempDir::~TempDir() {
  std::error_code error;
  std::filesystem::remove_all(root_, error);
}

std::string TempDir::write(const std::string &name, const std::string &content) const {
  std::ofstream(path(name), std::ios::binary) << content;
  return path(name);
}

namespace {

std::string quote(const std::string &argument) {
  std::string quoted = "'";
  for (char c : argument)
    quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string slurp(const std::string &path) {
  std::ifstream stream(path);
  std::stringstream content;
  content << stream.rdbuf();
  return content.str();
}

} // namespace

std::string file_bytes(const std::string &path) {
  std::ifstream stream(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(stream), {});
}

RunResult run_cli(const std::vector<std::string> &arguments) {
  TempDir capture;
  std::string command = quote(MEROMORPH_CLI);
  for (const std::string &argument : arguments)
    command += " " + quote(argument);
  command += " >" + quote(capture.path("out")) + " 2>" + quote(capture.path("err")) + " </dev/null";
  const int status = std::system(command.c_str());
  RunResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = slurp(capture.path("out"));
  result.err = slurp(capture.path("err"));
  return result;
}

void load(const std::string &path, Mesh &mesh) {
  ASSERT_NO_THROW(read_mesh(path, mesh)) << path;
}

void load_ply_attributes(const std::string &path, Mesh &mesh) {
  int mask = 0;
  ASSERT_EQ(vcg::tri::io::ImporterPLY<Mesh>::Open(mesh, path.c_str(), mask), 0) << path;
}

std::string off_text(const std::vector<std::array<double, 3>> &positions,
                     const std::vector<std::array<int, 3>> &triangles) {
  std::ostringstream text;
  text.precision(17);
  text << "OFF\n" << positions.size() << " " << triangles.size() << " 0\n";
  for (const auto &p : positions)
    text << p[0] << " " << p[1] << " " << p[2] << "\n";
  for (const auto &t : triangles)
    text << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  return text.str();
}

void arrays_of(const std::string &file, std::vector<std::array<double, 3>> &positions,
               std::vector<std::array<int, 3>> &triangles) {
  Mesh mesh;
  load(file, mesh);
  for (const MeshVertex &v : mesh.vert)
    positions.push_back({v.cP()[0], v.cP()[1], v.cP()[2]});
  for (const MeshFace &f : mesh.face)
    triangles.push_back(
        {index_of(mesh, f.cV(0)), index_of(mesh, f.cV(1)), index_of(mesh, f.cV(2))});
}

std::string cubes_sharing_an_edge_off() {
  // Unit cubes at the origin and at (1, 1, 0): they share the edge x = y = 1.
  std::vector<std::array<double, 3>> positions;
  std::map<std::array<double, 3>, int> index;
  std::vector<std::array<int, 3>> triangles;
  const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                           {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for (double offset : {0.0, 1.0}) {
    int corner[8];
    for (int c = 0; c < 8; ++c) {
      const std::array<double, 3> p{(c >> 2) + offset, ((c >> 1) & 1) + offset, double(c & 1)};
      if (!index.count(p)) {
        index[p] = int(positions.size());
        positions.push_back(p);
      }
      corner[c] = index[p];
    }
    for (const auto &q : quads) { // counter-clockwise seen from outside
      triangles.push_back({corner[q[0]], corner[q[1]], corner[q[2]]});
      triangles.push_back({corner[q[0]], corner[q[2]], corner[q[3]]});
    }
  }
  return off_text(positions, triangles);
}

} // namespace meromorph::test
