// Direct tests of the measurements on the sphere: map quality, sheets and texture coordinates.
#include "stage_units.h"

namespace meromorph {
namespace {

using namespace test;

TEST(MapQuality, TheIdentityIsExactAndAMirrorFoldsEverything) {
  Mesh mesh;
  make_icosphere(mesh, 3);
  const std::vector<Eigen::Vector3d> sphere = vertex_positions(mesh);
  const MapQuality identity = measure_map_quality(mesh, sphere, {});
  EXPECT_NEAR(identity.overall.angle_error_mean_degrees, 0.0, 1e-9);
  EXPECT_NEAR(identity.overall.quasi_conformal_max, 1.0, 1e-9);
  EXPECT_EQ(identity.overall.folded_faces, 0);
  EXPECT_NEAR(face_angle_error_degrees(mesh, sphere, 7), 0.0, 1e-9);
  std::vector<Eigen::Vector3d> mirrored = sphere;
  for (Eigen::Vector3d &p : mirrored)
    p.x() = -p.x();
  const MapQuality mirror = measure_map_quality(mesh, mirrored, {});
  EXPECT_EQ(mirror.overall.folded_faces, int(mesh.face.size()));
  EXPECT_EQ(mirror.folded_face_indices.size(), mesh.face.size());
}

TEST(Sheets, TheSquareOfAMoebiusMapHasTwoLayersEachCoveringTheSphere) {
  // z -> (chart at p)^2 on an icosphere: degree 2, branched at p and its antipode -p.
  Mesh mesh;
  make_icosphere(mesh, 4);
  const std::vector<Eigen::Vector3d> positions = vertex_positions(mesh);
  const int p = 0;
  int antipode = -1;
  for (size_t v = 0; v < positions.size(); ++v)
    if ((positions[v] + positions[size_t(p)]).norm() < 1e-9) antipode = int(v);
  ASSERT_GE(antipode, 0);
  std::vector<Eigen::Vector3d> sphere;
  const Eigen::Vector3d north(0, 0, 1);
  for (const Eigen::Vector3d &q : positions) {
    const Complex w = chart_at(positions[size_t(p)].normalized(), q.normalized());
    sphere.push_back(from_chart(north, w * w));
  }
  const std::vector<int> branch = {p, antipode};
  const Sheets sheets = label_sheets(mesh, build_mesh_edges(mesh), sphere, branch, 2);
  ASSERT_EQ(sheets.count, 2);
  ASSERT_EQ(sheets.coverage.size(), 2u);
  for (double coverage : sheets.coverage)
    EXPECT_NEAR(coverage, 1.0, 0.02);
  ASSERT_EQ(sheets.face_layer.size(), mesh.face.size());
  ASSERT_EQ(sheets.vertex_layer.size(), mesh.vert.size());
  const Branching branching = analyse_branching(mesh, sphere, 2);
  EXPECT_EQ(branching.degree, 2);
  EXPECT_EQ(branching.branch_vertices.size(), 2u);
}

TEST(TextureCoordinates, LongitudeLatitudeAndTheSeam) {
  auto uv = [](double x, double y, double z) {
    return texture_coordinate(Eigen::Vector3d(x, y, z), UvKind::spherical);
  };
  EXPECT_NEAR(uv(1, 0, 0)[0], 0.5, 1e-12);
  EXPECT_NEAR(uv(1, 0, 0)[1], 0.5, 1e-12);
  EXPECT_NEAR(uv(0, 1, 0)[0], 0.75, 1e-12);
  EXPECT_NEAR(uv(0, 0, 1)[1], 0.0, 1e-12);
  EXPECT_NEAR(uv(0, 0, -1)[1], 1.0, 1e-12);
  const Eigen::Vector3d w(0.3, -0.4, 0.5);
  const std::array<double, 2> plane = texture_coordinate(w.normalized(), UvKind::stereographic);
  const Complex expected = to_plane(w.normalized());
  EXPECT_NEAR(plane[0], expected.real(), 1e-12);
  EXPECT_NEAR(plane[1], expected.imag(), 1e-12);
  // A face across longitude 180 degrees: its wedges are unwrapped, no corner a whole turn away.
  MeshArrays arrays;
  arrays.positions = {Point3(-1, 0.05, 0), Point3(-1, -0.05, 0), Point3(-1, 0, 0.1)};
  arrays.triangles = {{0, 1, 2}};
  Mesh triangle;
  mesh_from_arrays(arrays, triangle);
  std::vector<Eigen::Vector3d> sphere = unit_positions(triangle);
  const TextureCoordinates texture = texture_coordinates(triangle, sphere, UvKind::spherical);
  EXPECT_GT(std::abs(texture.vertex[0][0] - texture.vertex[1][0]), 0.9); // the seam
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_LT(std::abs(texture.wedge[0][size_t(i)][0] - texture.wedge[0][size_t(j)][0]), 0.1);
}

} // namespace
} // namespace meromorph
