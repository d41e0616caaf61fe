// Broken files: a clear error with the path (and line), never a crash or a half-read mesh.
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "common/errors.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"
#include "shapes/generated_surfaces.h"
#include "test_support.h"
#include "written_map.h"

namespace meromorph {
namespace {

using test::file_bytes;
using test::TempDir;

// Reading `path` throws an error of type E whose message contains `expected`.
template <class E> void expect_read_error(const std::string &path, const std::string &expected) {
  Mesh mesh;
  try {
    read_mesh(path, mesh);
    ADD_FAILURE() << path << " was read without error";
  } catch (const E &error) {
    EXPECT_NE(std::string(error.what()).find(expected), std::string::npos)
        << "message: " << error.what() << "\nexpected to contain: " << expected;
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << "names the file";
  } catch (const std::exception &error) {
    ADD_FAILURE() << path << ": wrong error type: " << error.what();
  }
}

TEST(BadFiles, EmptyFilesOfEveryFormat) {
  TempDir dir;
  for (const char *name : {"empty.off", "empty.obj", "empty.ply", "empty.stl"})
    expect_read_error<InputError>(dir.write(name, ""), "the file is empty");
}

TEST(BadFiles, MissingFileAndUnsupportedExtension) {
  TempDir dir;
  expect_read_error<ArgumentError>(dir.path("missing.off"), "no such file");
  expect_read_error<ArgumentError>(dir.write("mesh.xyz", "1 2 3\n"), "'.xyz'");
}

TEST(BadFiles, TruncatedOff) {
  TempDir dir;
  const std::string eight = file_bytes(test::data_path("eight.off"));
  // Cut mid-line, and cut at a line's end.
  expect_read_error<InputError>(dir.write("cut_early.off", eight.substr(0, 2000)),
                                "more than a file of 2000 bytes can hold (truncated, or a wrong "
                                "header)");
  expect_read_error<InputError>(
      dir.write("cut_in_vertices.off", "OFF\n# " + std::string(100, '-') + "\n3 1 0\n0 0 0\n1 0"),
      "ends in the middle of vertex 1 of the 3 vertices its header announces (truncated?)");
  expect_read_error<InputError>(dir.write("cut_in_faces.off", eight.substr(0, eight.size() - 500)),
                                "of the 1536 faces its header announces (truncated?)");
  const size_t line_end = eight.rfind('\n', eight.size() - 500) + 1;
  expect_read_error<InputError>(dir.write("cut_at_line.off", eight.substr(0, line_end)),
                                "the file ends after 1500 of the 1536 faces its header announces");
}

TEST(BadFiles, TruncatedBinaryPly) {
  TempDir dir;
  Mesh sphere;
  make_icosphere(sphere, 2);
  write_mesh(sphere, dir.path("whole.ply"));
  const std::string whole = file_bytes(dir.path("whole.ply"));
  expect_read_error<InputError>(dir.write("cut.ply", whole.substr(0, whole.size() / 2)),
                                "more vertices and faces than a file of");
  // Cut inside the last face: the counts still fit, the data does not.
  expect_read_error<InputError>(dir.write("cut_late.ply", whole.substr(0, whole.size() - 3)),
                                "the file ends inside face 319 (truncated");
}

TEST(BadFiles, PlyHeaderLiesAboutItsCounts) {
  TempDir dir;
  expect_read_error<InputError>(
      dir.write("lie.ply", "ply\nformat ascii 1.0\nelement vertex 10\nproperty float x\n"
                           "property float y\nproperty float z\nelement face 2\n"
                           "property list uchar int vertex_indices\nend_header\n"
                           "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
      "announces more vertices and faces than a file of");
}

TEST(BadFiles, HeaderCountsLargerThanTheFileCanHold) {
  TempDir dir;
  expect_read_error<InputError>(dir.write("huge.off", "OFF\n999999999999 1 0\n0 0 0\n"),
                                "more than a file of 27 bytes can hold");
  expect_read_error<InputError>(
      dir.write("huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\n"
                            "property float x\nproperty float y\nproperty float z\n"
                            "element face 2\nproperty list uchar int vertex_indices\n"
                            "end_header\n0 0 0\n"),
      "more vertices and faces than a file of");
  expect_read_error<InputError>(dir.write("overflow.ply",
                                          "ply\nformat ascii 1.0\nelement vertex 999999999999\n"
                                          "property float x\nproperty float y\nproperty float z\n"
                                          "end_header\n0 0 0\n"),
                                "overflow.ply:3: element 'vertex' has the count '999999999999', "
                                "which is not a whole number from 0 to 2147483647");
}

TEST(BadFiles, IndicesOutOfRangeNameTheLine) {
  TempDir dir;
  expect_read_error<InputError>(
      dir.write("oob.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n"),
      "oob.off:6: face 0 refers to vertex 9, but the file has vertices 0..2");
  expect_read_error<InputError>(dir.write("oob.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
                                "oob.obj:4: face refers to vertex 9");
  expect_read_error<InputError>(dir.write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"),
                                "OBJ counts vertices from 1");
  expect_read_error<InputError>(
      dir.write("oob.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                           "property float y\nproperty float z\nelement face 1\n"
                           "property list uchar int vertex_indices\nend_header\n"
                           "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
      "oob.ply:13: face 0 refers to vertex 7, but the file has vertices 0..2");
}

TEST(BadFiles, GarbageInsideText) {
  TempDir dir;
  expect_read_error<InputError>(
      dir.write("word.off", "OFF\n3 1 0\n0 0 zero\n1 0 0\n0 1 0\n3 0 1 2\n"),
      "word.off:3: 'zero' is not a number");
  expect_read_error<InputError>(dir.write("short.obj", "v 0 0\n"), "needs three coordinates");
  expect_read_error<InputError>(dir.write("facet.stl", "solid x\nfacet normal 0 0 1\nouter loop\n"
                                                       "vertex 0 0 0\nvertex 1 0 0\nendloop\n"
                                                       "endfacet\nendsolid x\n"),
                                "a facet must have exactly 3 vertices, this one has 2");
}

TEST(BadFiles, BinaryContentWithTheWrongExtension) {
  TempDir dir;
  Mesh sphere;
  make_icosphere(sphere, 1);
  write_mesh(sphere, dir.path("sphere.ply"));
  write_mesh(sphere, dir.path("sphere.stl"));
  const std::string ply = file_bytes(dir.path("sphere.ply"));
  const std::string stl = file_bytes(dir.path("sphere.stl"));
  expect_read_error<InputError>(dir.write("ply_named.off", ply),
                                "its content is PLY; rename it to .ply");
  expect_read_error<InputError>(dir.write("ply_named.obj", ply), "its content is PLY");
  expect_read_error<InputError>(dir.write("stl_named.ply", stl), "its content is STL");
  expect_read_error<InputError>(dir.write("stl_named.off", stl), "its content is STL");
  std::string noise(3000, '\0');
  for (size_t i = 0; i < noise.size(); ++i)
    noise[i] = char((i * 7919) % 251);
  expect_read_error<InputError>(dir.write("noise.obj", noise), "holds binary data");
  expect_read_error<InputError>(dir.write("noise.ply", noise), "not a PLY file");
  expect_read_error<InputError>(dir.write("noise.stl", noise), "not an STL file");
  expect_read_error<InputError>(dir.write("noise.off", noise), "not an OFF file");
}

// Inputs shaped to make work quadratic get linear work: one OBJ polygon of 200,000 corners (a
// fan: every half-edge at one vertex; validation paired them in time quadratic in the valence,
// 15 s at 100,000) and one quad repeated 40,000 times (80,000 faces on four vertices; the
// non-manifold split and the duplicate search were quadratic, 11 s at 10,000). The bound below
// is a hang guard, a hundred times what the work takes here, not a timing.
TEST(BadFiles, ValencesAndRepeatsThatMadeWorkQuadraticStayLinear) {
  TempDir dir;
  std::ostringstream fan, quads;
  const int corners = 200000;
  for (int i = 0; i < corners; ++i)
    fan << "v " << std::cos(2 * M_PI * i / corners) << " " << std::sin(2 * M_PI * i / corners)
        << " 0\n";
  fan << "f";
  for (int i = 1; i <= corners; ++i)
    fan << " " << i;
  fan << "\n";
  quads << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  for (int i = 0; i < 40000; ++i)
    quads << "f 1 2 3 4\n";
  const auto start = std::chrono::steady_clock::now();
  const test::RunResult info = test::run_cli({"info", dir.write("fan.obj", fan.str()), "--strict"});
  EXPECT_EQ(info.exit_code, 3) << info.err; // open: refused when holes are not to be closed
  EXPECT_NE(info.out.find("of 200000 edges"), std::string::npos) << info.out;
  // The repeats are doubled faces, left out of the computation: one quad is mapped (its hole
  // closed), and all 80,000 triangles are written.
  const test::RunResult split =
      test::run_cli({"param", dir.write("quads.obj", quads.str()), "-o", dir.path("out.ply"),
                     "--sphere", dir.path("sphere.ply"), "--quiet"});
  EXPECT_EQ(split.exit_code, 0) << split.err;
  EXPECT_EQ(test::read_written_mesh(dir.path("sphere.ply")).triangles.size(), 80000u);
  const test::RunResult strict =
      test::run_cli({"param", dir.path("quads.obj"), "-o", dir.path("strict.ply"),
                     "--split-nonmanifold", "--close-holes", "--strict", "--quiet"});
  EXPECT_EQ(strict.exit_code, 3) << strict.err;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60.0);
}

} // namespace
} // namespace meromorph
