// Reading every format, polygons, comment lines, and round trips through vcglib's exporters.
#include <gtest/gtest.h>

#include "common/errors.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"
#include "mesh/mesh_from_arrays.h"
#include "mesh/topology.h"
#include "shapes/generated_surfaces.h"
#include "test_support.h"

namespace meromorph {
namespace {

using test::data_path;
using test::TempDir;

struct SharedMesh {
  const char *name;
  int vertices;
  int faces;
};

TEST(Reading, SharedMeshesHaveTheirDocumentedCounts) {
  const SharedMesh meshes[] = {
      {"sphere.off", 482, 960},           {"maxplanck.nf25k.off", 12556, 25108},
      {"torus.off", 1200, 2400},          {"knot.obj", 1440, 2880},
      {"kitten.nf20k.off", 10000, 20000}, {"kitten.nv40k.off", 40000, 80000},
      {"eight.off", 766, 1536},           {"eight.hole.off", 765, 1530},
      {"eight.open.off", 814, 1536},      {"bunny.off", 34834, 69451},
      {"face.off", 1180, 2000},
  };
  for (const SharedMesh &expected : meshes) {
    Mesh mesh;
    test::load(data_path(expected.name), mesh);
    EXPECT_EQ(mesh.VN(), expected.vertices) << expected.name;
    EXPECT_EQ(mesh.FN(), expected.faces) << expected.name;
  }
}

// vcglib's own OBJ importer silently drops the 6 faces of knot.obj whose texture indices are out
// of range; ours reads geometry only and keeps them all.
TEST(Reading, ObjKeepsFacesWithBrokenTextureIndices) {
  Mesh mesh;
  test::load(data_path("knot.obj"), mesh);
  EXPECT_EQ(mesh.FN(), 2880);
  EXPECT_EQ(compute_topology(mesh).genus, 1);
}

TEST(Reading, OffWithCommentLineAfterHeader) {
  TempDir dir;
  const std::string path =
      dir.write("commented.off", "OFF\n# made by hand\n4 4 0\n# vertices\n"
                                 "0 0 0\n1 0 0 # trailing comment\n0 1 0\n0 0 1\n"
                                 "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  Mesh mesh;
  test::load(path, mesh);
  EXPECT_EQ(mesh.VN(), 4);
  EXPECT_EQ(mesh.FN(), 4);
  EXPECT_EQ(mesh.vert[1].P()[0], 1.0);
}

TEST(Reading, ObjPolygonsAreTriangulated) {
  TempDir dir;
  // A cube of six quads, with texture and normal indices, one face with negative indices.
  const std::string path = dir.write(
      "cube.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                  "vt 0 0\nvn 0 0 1\n"
                  "f 1/1/1 4/1/1 3/1/1 2/1/1\nf 5//1 6//1 7//1 8//1\nf 1 2 6 5\n"
                  "f 2 3 7 6\nf 3 4 8 7\nf -8 -4 -1 -5\n");
  Mesh mesh;
  MeshSource source = read_mesh(path, mesh);
  EXPECT_EQ(mesh.VN(), 8);
  EXPECT_EQ(mesh.FN(), 12);
  ASSERT_FALSE(source.notes.empty());
  EXPECT_NE(source.notes[0].find("triangulated 6 polygonal faces"), std::string::npos);
  const Topology topology = compute_topology(mesh);
  EXPECT_EQ(topology.genus, 0);
  EXPECT_TRUE(topology.closed_manifold());
}

TEST(Reading, OffPolygonsAndPlyPolygonsAreTriangulated) {
  TempDir dir;
  const std::string cube_faces =
      "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
  const std::string cube_vertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n";
  Mesh off_mesh, ply_mesh;
  test::load(dir.write("cube.off", "OFF\n8 6 0\n" + cube_vertices + cube_faces), off_mesh);
  test::load(dir.write("cube.ply", "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\n"
                                   "property float y\nproperty float z\nelement face 6\n"
                                   "property list uchar int vertex_indices\nend_header\n" +
                                       cube_vertices + cube_faces),
             ply_mesh);
  for (Mesh *mesh : {&off_mesh, &ply_mesh}) {
    EXPECT_EQ(mesh->FN(), 12);
    EXPECT_EQ(compute_topology(*mesh).genus, 0);
  }
}

TEST(Reading, StlCornersAreWelded) {
  TempDir dir;
  Mesh sphere;
  make_icosphere(sphere, 2);
  for (bool binary : {true, false}) {
    const std::string path = dir.path(binary ? "binary.stl" : "ascii.stl");
    WriteOptions options;
    options.binary = binary;
    write_mesh(sphere, path, options);
    Mesh mesh;
    MeshSource source = read_mesh(path, mesh);
    EXPECT_EQ(mesh.VN(), sphere.VN()) << path;
    EXPECT_EQ(mesh.FN(), sphere.FN()) << path;
    EXPECT_EQ(compute_topology(mesh).genus, 0) << path;
    ASSERT_EQ(source.notes.size(), 1u);
    EXPECT_NE(source.notes[0].find("welded"), std::string::npos);
  }
}

TEST(Reading, RoundTripKeepsVerticesAndFacesInOrder) {
  TempDir dir;
  Mesh original;
  make_genus_surface(original, 2, 16);
  const MeshArrays expected = arrays_from_mesh(original);
  struct Case {
    const char *name;
    bool binary;
    double tolerance; // the exporters' precision: PLY keeps doubles, OBJ/OFF print decimals
  };
  for (const Case &c : {Case{"binary.ply", true, 0.0}, Case{"ascii.ply", false, 1e-6},
                        Case{"mesh.obj", false, 1e-5}, Case{"mesh.off", false, 1e-5}}) {
    WriteOptions options;
    options.binary = c.binary;
    write_mesh(original, dir.path(c.name), options);
    Mesh mesh;
    test::load(dir.path(c.name), mesh);
    const MeshArrays read = arrays_from_mesh(mesh);
    ASSERT_EQ(read.positions.size(), expected.positions.size()) << c.name;
    ASSERT_EQ(read.triangles, expected.triangles) << c.name;
    double worst = 0;
    for (size_t v = 0; v < read.positions.size(); ++v)
      worst = std::max(worst, (read.positions[v] - expected.positions[v]).Norm());
    EXPECT_LE(worst, c.tolerance) << c.name;
  }
}

TEST(Writing, NeverWritesOverTheInput) {
  TempDir dir;
  const std::string input = dir.write("in.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  Mesh mesh;
  test::load(input, mesh);
  EXPECT_THROW(write_mesh(mesh, input, {}, {input}), ArgumentError);
  EXPECT_THROW(write_mesh(mesh, dir.path("./in.off"), {}, {input}), ArgumentError);
  EXPECT_NO_THROW(write_mesh(mesh, dir.path("out.off"), {}, {input}));
}

} // namespace
} // namespace meromorph
