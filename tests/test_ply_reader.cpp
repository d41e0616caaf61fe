// The strict PLY reader: every encoding and type real exporters write is read; every lying count,
// out-of-range index, odd list and malformed number is refused with the file and where, never a
// crash (each case below crashed or was misread by vcglib's importer).
#include <cstdint>
#include <cstring>
#include <fstream>

#include <gtest/gtest.h>

#include "common/errors.h"
#include "io/mesh_reader.h"
#include "test_support.h"

namespace meromorph {
namespace {

using test::TempDir;

const std::string cube_header = "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\n"
                                "property float y\nproperty float z\nelement face 6\n"
                                "property list uchar int vertex_indices\nend_header\n";
const std::string cube_vertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n";
const std::string cube_faces = "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

// Reading `content` as a .ply file fails with InputError naming the file and saying `expected`.
void expect_refused(const std::string &content, const std::string &expected) {
  TempDir dir;
  const std::string path = dir.write("bad.ply", content);
  Mesh mesh;
  try {
    read_mesh(path, mesh);
    ADD_FAILURE() << "read without error:\n" << content.substr(0, 400);
  } catch (const InputError &error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(expected), std::string::npos)
        << "message: " << message << "\nexpected to contain: " << expected;
    EXPECT_NE(message.find(path), std::string::npos) << message;
  } catch (const std::exception &error) {
    ADD_FAILURE() << "wrong error type: " << error.what();
  }
}

void expect_cube(const std::string &content, const std::string &name = "cube.ply") {
  TempDir dir;
  Mesh mesh;
  ASSERT_NO_THROW(read_mesh(dir.write(name, content), mesh));
  EXPECT_EQ(mesh.VN(), 8);
  EXPECT_EQ(mesh.FN(), 12) << "six quads, two triangles each";
  EXPECT_EQ(mesh.vert[6].cP(), Point3(1, 1, 1));
}

template <class T> void put(std::string &bytes, T value, bool big_endian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian) std::reverse(raw, raw + sizeof(T));
  bytes.append(raw, sizeof(T));
}

// The cube in binary, with a per-face list of 255 floats beside the corners (as exporters write
// per-face texture coordinates) and an unknown element after the faces.
std::string binary_cube(bool big_endian) {
  std::string bytes = std::string("ply\nformat ") +
                      (big_endian ? "binary_big_endian" : "binary_little_endian") +
                      " 1.0\ncomment made by a test\nelement vertex 8\nproperty double x\n"
                      "property double y\nproperty double z\nproperty uchar red\n"
                      "element face 6\nproperty list int uint vertex_indices\n"
                      "property list uchar float texcoord\nelement camera 1\n"
                      "property short view\nend_header\n";
  const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (const auto &p : corners) {
    for (double c : p)
      put(bytes, c, big_endian);
    put(bytes, uint8_t(200), big_endian);
  }
  const uint32_t quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (const auto &q : quads) {
    put(bytes, int32_t(4), big_endian);
    for (uint32_t v : q)
      put(bytes, v, big_endian);
    put(bytes, uint8_t(255), big_endian);
    for (int k = 0; k < 255; ++k)
      put(bytes, float(k), big_endian);
  }
  put(bytes, int16_t(7), big_endian);
  return bytes;
}

TEST(PlyReader, ReadsEveryEncodingAndSkipsWhatItDoesNotUse) {
  expect_cube(cube_header + cube_vertices + cube_faces);
  expect_cube("\xEF\xBB\xBF" + cube_header + cube_vertices + cube_faces, "bom.ply");
  std::string crlf;
  for (char c : cube_header + cube_vertices + cube_faces)
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  expect_cube(crlf, "crlf.ply");
  expect_cube(binary_cube(false), "little.ply");
  expect_cube(binary_cube(true), "big.ply");
  // No newline after the last face; faces declared before the vertices.
  std::string last = cube_header + cube_vertices + cube_faces;
  last.pop_back();
  expect_cube(last, "no_final_newline.ply");
  expect_cube("ply\nformat ascii 1.0\nelement face 6\nproperty list uchar int vertex_indices\n"
              "element vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
              "end_header\n" +
                  cube_faces + cube_vertices,
              "faces_first.ply");
}

// Asked for, the vertex element's other scalar properties come back by name and type, in both
// byte orders (the binary cube has a uchar `red` of 200 per vertex); not asked for, none.
TEST(PlyReader, KeepsTheVerticesOtherValuesWhenAsked) {
  for (bool big_endian : {false, true}) {
    TempDir dir;
    const std::string path = dir.write("values.ply", binary_cube(big_endian));
    Mesh mesh;
    const MeshSource source = read_mesh(path, mesh, {}, true);
    ASSERT_EQ(source.vertex_values.size(), 1u);
    const VertexValues &red = source.vertex_values.front();
    EXPECT_EQ(red.name, "red");
    EXPECT_TRUE(red.integer && red.byte);
    EXPECT_EQ(red.values, std::vector<double>(8, 200.0));
    EXPECT_TRUE(read_mesh(path, mesh).vertex_values.empty());
  }
  TempDir dir;
  Mesh mesh;
  const MeshSource source = read_mesh(
      dir.write("ascii.ply", "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\n"
                             "property float quality\nproperty float y\nproperty float z\n"
                             "property int label\nelement face 6\n"
                             "property list uchar int vertex_indices\nend_header\n"
                             "0 0.5 0 0 3\n1 1.5 0 0 3\n1 2.5 1 0 3\n0 3.5 1 0 3\n"
                             "0 4.5 0 1 4\n1 5.5 0 1 4\n1 6.5 1 1 4\n0 7.5 1 1 4\n" +
                                 cube_faces),
      mesh, {}, true);
  ASSERT_EQ(source.vertex_values.size(), 2u);
  EXPECT_EQ(source.vertex_values[0].name, "quality");
  EXPECT_FALSE(source.vertex_values[0].integer);
  EXPECT_EQ(source.vertex_values[0].values[7], 7.5);
  EXPECT_EQ(source.vertex_values[1].name, "label");
  EXPECT_TRUE(source.vertex_values[1].integer && !source.vertex_values[1].byte);
  EXPECT_EQ(source.vertex_values[1].values[4], 4.0);
  EXPECT_EQ(mesh.vert[6].cP(), Point3(1, 1, 1));
}

TEST(PlyReader, RefusesLyingCountsAndIndices) {
  expect_refused("ply\nformat ascii 1.0\nelement vertex\nproperty float x\nend_header\n",
                 "bad.ply:3: expected 'element NAME COUNT'");
  expect_refused("ply\nformat ascii 1.0\nelement vertex 4294967300\nproperty float x\n"
                 "end_header\n",
                 "not a whole number from 0 to 2147483647");
  expect_refused("ply\nformat ascii 1.0\nelement vertex -3\nend_header\n",
                 "the count '-3', which is not a whole number");
  expect_refused(cube_header + cube_vertices + "4 0 3 2 1\n4 4 5 6 12\n" + cube_faces,
                 "bad.ply:19: face 1 refers to vertex 12, but the file has vertices 0..7");
  expect_refused(cube_header + cube_vertices + "-1 0 1 2\n" + cube_faces,
                 "-1 in face 0 does not fit its declared type");
  expect_refused(cube_header + cube_vertices + "9 0 1 2 3 4 5 6 7 0\n" + cube_faces,
                 "face 0 has the list count 9 (allowed: 0 to 8)");
  expect_refused(cube_header + cube_vertices + "2 0 1\n" + cube_faces,
                 "face 0 has 2 corners; a face needs at least 3");
  expect_refused(cube_header + cube_vertices + "0\n" + cube_faces,
                 "face 0 has 0 corners; a face needs at least 3");
  expect_refused("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                 "property float z\nelement vertex 1\nproperty float x\nend_header\n0 0 0\n0\n",
                 "bad.ply:7: element 'vertex' is declared twice");
  expect_refused("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                 "end_header\n0 0\n",
                 "the vertex element has no scalar property 'z'");
  expect_refused("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                 "property float z\nelement face 1\nproperty list uchar float vertex_indices\n"
                 "end_header\n0 0 0\n3 0 0 0\n",
                 "no integer list 'vertex_indices'");
}

TEST(PlyReader, RefusesMalformedNumbersAndHeaders) {
  for (const char *number : {"+-1", "0x1p3", "1e", "1.0.0", "--2", "nan(", "1,5"})
    expect_refused(cube_header + std::string(number) + " 0 0\n" + cube_vertices.substr(6) +
                       cube_faces,
                   std::string("'") + number + "' in vertex 0 is not a number");
  expect_refused(cube_header + cube_vertices + "4 0 3 2.5 1\n" + cube_faces.substr(10),
                 "'2.5' in face 0 is not a whole number");
  expect_refused(cube_header + cube_vertices + "300 0 3 2 1\n" + cube_faces.substr(10),
                 "300 in face 0 does not fit its declared type");
  expect_refused("ply\nformat ascii 2.0\nend_header\n", "bad.ply:2: expected 'format ascii 1.0'");
  expect_refused("ply\nformat ascii 1.0\nelement vertex 0\nproperty float128 x\nend_header\n",
                 "unknown property type 'float128'");
  expect_refused("ply\nformat ascii 1.0\nelement vertex 0\nproperty list float int x\n"
                 "end_header\n",
                 "a list's count type must be an integer type");
  expect_refused("ply\nformat ascii 1.0\nelement vertex 0\n", "no 'end_header' line");
  expect_refused("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float x\n",
                 "property 'x' is declared twice");
  expect_refused("ply\nelement vertex 1\n", "'element' before the 'format' line");
  expect_refused("ply\nformat ascii 1.0\nproperty float x\n", "'property' before any 'element'");
  expect_refused("ply\nformat ascii 1.0\nbanana\n", "unknown PLY header line 'banana'");
}

TEST(PlyReader, RefusesTruncatedBinaryAtItsByteOffset) {
  const std::string whole = binary_cube(false);
  // Cut every few bytes through the data: always a clear error, never a crash.
  const size_t data = whole.find("end_header\n") + 11;
  for (size_t cut = data; cut < whole.size(); cut += 97) {
    TempDir dir;
    Mesh mesh;
    const std::string path = dir.write("cut.ply", whole.substr(0, cut));
    EXPECT_THROW(read_mesh(path, mesh), InputError) << "cut at " << cut;
  }
  expect_refused(whole.substr(0, whole.size() - 1), "at byte");
  // A per-face list longer than the rest of the file.
  std::string lying = whole;
  const size_t first_list = data + 8 * 25 + 4 + 16;
  lying[first_list] = char(255);
  std::string truncated = lying.substr(0, first_list + 1 + 40);
  expect_refused(truncated, "face 0");
}

} // namespace
} // namespace meromorph
