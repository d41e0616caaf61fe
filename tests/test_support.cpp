#include "test_support.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

#include <gtest/gtest.h>

#include <cstring>

#include <wrap/io_trimesh/import_ply.h>

#include "mesh_reader.h"

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

} // namespace meromorph::test
