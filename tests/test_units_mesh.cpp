// Direct tests of the mesh stages, each on inputs whose answer is known exactly: taking
// non-manifold spots apart, splitting into parts and closing holes, taking out zero-area faces,
// the cotangent Laplacian's assembly.
#include "stage_units.h"

namespace meromorph {
namespace {

using namespace test;

TEST(NonmanifoldSplit, TwoSpheresTouchingAtAVertexComeApart) {
  int shared = -1;
  const MeshArrays arrays = spheres_touching_at_a_vertex(shared);
  Mesh touching, split;
  mesh_from_arrays(arrays, touching);
  EXPECT_EQ(compute_topology(touching).euler, 3); // two spheres less a vertex
  const NonmanifoldSplit result = split_nonmanifold(touching, split);
  EXPECT_EQ(result.added_vertices, 1);
  EXPECT_EQ(result.split_vertices, std::vector<int>{shared});
  EXPECT_TRUE(result.split_edges.empty());
  ASSERT_EQ(result.source_vertex.size(), touching.vert.size() + 1);
  EXPECT_EQ(result.source_vertex.back(), shared);
  const Topology topology = compute_topology(split);
  EXPECT_EQ(topology.euler, 4);
  EXPECT_EQ(topology.component_faces.size(), 2u);
  EXPECT_TRUE(topology.boundary_loops.empty());
  EXPECT_EQ(topology.non_manifold_edges, 0);
  ASSERT_EQ(split.face.size(), touching.face.size());
  // The faces keep their order, and each corner's position.
  for (size_t f = 0; f < split.face.size(); ++f)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(split.face[f].cP(k), touching.face[f].cP(k)) << "face " << f;
}

TEST(NonmanifoldSplit, TwoCubesSharingAnEdgeBecomeTwoClosedCubes) {
  const std::string path = ::testing::TempDir() + "cubes_sharing_an_edge.off";
  { std::ofstream(path) << test::cubes_sharing_an_edge_off(); }
  Mesh cubes, split;
  test::load(path, cubes);
  EXPECT_GT(compute_topology(cubes).non_manifold_edges, 0);
  const NonmanifoldSplit result = split_nonmanifold(cubes, split);
  ASSERT_EQ(result.split_edges.size(), 1u);
  EXPECT_EQ(result.added_vertices, 2); // both ends of the edge
  const Topology topology = compute_topology(split);
  EXPECT_EQ(topology.non_manifold_edges, 0);
  EXPECT_TRUE(topology.boundary_loops.empty());
  EXPECT_EQ(topology.component_faces, (std::vector<int>{12, 12}));
  EXPECT_EQ(topology.euler, 4);
}

TEST(SurfaceParts, TwoSpheresAreTwoPartsAndAHoleIsClosed) {
  MeshArrays arrays = icosphere_arrays(1);
  const size_t first_vertices = arrays.positions.size(), first_faces = arrays.triangles.size();
  const MeshArrays second = icosphere_arrays(2);
  for (const Point3 &p : second.positions)
    arrays.positions.push_back(p + Point3(3, 0, 0));
  for (const auto &t : second.triangles)
    arrays.triangles.push_back(
        {t[0] + int(first_vertices), t[1] + int(first_vertices), t[2] + int(first_vertices)});
  arrays.triangles.erase(arrays.triangles.begin() + long(first_faces)); // a hole in the second
  Mesh two;
  mesh_from_arrays(arrays, two);
  const SurfaceParts parts = split_into_closed_parts(two, true);
  ASSERT_EQ(parts.parts.size(), 2u);
  EXPECT_EQ(parts.parts[0].mesh.face.size(), first_faces);
  ASSERT_EQ(parts.holes.size(), 1u);
  EXPECT_EQ(parts.holes[0].part, 1);
  EXPECT_EQ(parts.holes[0].edges, 3);
  for (const SurfacePart &part : parts.parts) {
    const Topology topology = compute_topology(part.mesh);
    EXPECT_TRUE(topology.closed_manifold());
    EXPECT_EQ(topology.genus, std::optional<int>(0));
  }
  // Every input vertex and face is in its part, and comes back from there.
  for (size_t v = 0; v < two.vert.size(); ++v) {
    const SurfacePart &part = parts.parts[size_t(parts.part_of_vertex[v])];
    EXPECT_EQ(part.source_vertex[size_t(parts.vertex_in_part[v])], int(v));
  }
  for (size_t f = 0; f < two.face.size(); ++f) {
    const SurfacePart &part = parts.parts[size_t(parts.part_of_face[f])];
    EXPECT_EQ(part.source_face[size_t(parts.face_in_part[f])], int(f));
  }
}

// An edge (a, b) of an icosphere split at a point: a new vertex m on the edge, its two faces
// split in four.
MeshArrays with_edge_split(double where) {
  MeshArrays arrays = icosphere_arrays(2);
  const std::array<int, 3> first = arrays.triangles[0];
  const int a = first[0], b = first[1], c = first[2];
  size_t across = 0;
  int d = -1;
  for (size_t f = 1; f < arrays.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k)
      if (arrays.triangles[f][size_t(k)] == b && arrays.triangles[f][size_t((k + 1) % 3)] == a) {
        across = f;
        d = arrays.triangles[f][size_t((k + 2) % 3)];
      }
  const int m = int(arrays.positions.size());
  arrays.positions.push_back(arrays.positions[size_t(a)] * (1 - where) +
                             arrays.positions[size_t(b)] * where);
  arrays.triangles[0] = {a, m, c};
  arrays.triangles[across] = {m, a, d};
  arrays.triangles.push_back({m, b, c});
  arrays.triangles.push_back({b, m, d});
  return arrays;
}

int zero_area_count(const Mesh &mesh) {
  int count = 0;
  for (const MeshFace &face : mesh.face)
    count += has_zero_area(face);
  return count;
}

TEST(ZeroAreaFaces, ANeedleIsCollapsedAndTheSurfaceKept) {
  Mesh needled, work;
  mesh_from_arrays(with_edge_split(0.0), needled); // m on a: two needles
  ASSERT_EQ(zero_area_count(needled), 2);
  const ZeroAreaFix fix = take_out_zero_area_faces(needled, work);
  EXPECT_EQ(fix.zero_area_faces.size(), 2u);
  EXPECT_EQ(fix.collapsed_edges, 1);
  EXPECT_EQ(zero_area_count(work), 0);
  EXPECT_EQ(work.face.size(), needled.face.size() - 2);
  EXPECT_EQ(compute_topology(work).genus, std::optional<int>(0));
  ASSERT_EQ(fix.vertex_in_work.size(), needled.vert.size());
  ASSERT_EQ(fix.face_in_work.size(), needled.face.size());
  for (size_t v = 0; v < needled.vert.size(); ++v) {
    if (fix.vertex_in_work[v] >= 0) {
      EXPECT_EQ(work.vert[size_t(fix.vertex_in_work[v])].cP(), needled.vert[v].cP());
    }
  }
}

TEST(ZeroAreaFaces, ACapIsFlippedAway) {
  // The face (a, m, c) with m at the middle of a long side: move c onto the side (a, b) of its
  // other face, which makes that face a cap.
  MeshArrays arrays = icosphere_arrays(2);
  const std::array<int, 3> face = arrays.triangles[0];
  arrays.positions[size_t(face[2])] =
      (arrays.positions[size_t(face[0])] + arrays.positions[size_t(face[1])]) * 0.5;
  Mesh capped, work;
  mesh_from_arrays(arrays, capped);
  ASSERT_GE(zero_area_count(capped), 1);
  const ZeroAreaFix fix = take_out_zero_area_faces(capped, work);
  EXPECT_GE(fix.flipped_edges + fix.collapsed_edges, 1);
  EXPECT_EQ(zero_area_count(work), 0);
  EXPECT_EQ(compute_topology(work).genus, std::optional<int>(0));
  EXPECT_EQ(fix.face_in_work[0], -1); // the cap itself changed
}

// The Laplacian as the sum over edges of w (e_i - e_j)(e_i - e_j)^T, compared entry by entry with
// a dense sum, also where an intrinsic triangulation joins two vertices twice or a vertex to
// itself.
TEST(CotanLaplacian, SumOverEdgesWithRepeatedEdgesAndLoops) {
  MeshEdges edges;
  edges.vertices = {{0, 1}, {1, 2}, {2, 0}, {3, 1}, {1, 3}, {2, 2}, {3, 0}, {0, 1}};
  const std::vector<double> weights = {0.5, -0.25, 2.0, 1.0, 0.75, 3.0, 1.5, 0.125};
  const Eigen::SparseMatrix<double> laplacian = cotan_laplacian(4, edges, weights);
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(4, 4);
  for (size_t e = 0; e < weights.size(); ++e) {
    Eigen::Vector4d d = Eigen::Vector4d::Zero();
    d[edges.vertices[e][0]] += 1;
    d[edges.vertices[e][1]] -= 1;
    expected += weights[e] * d * d.transpose();
  }
  EXPECT_LT((Eigen::MatrixXd(laplacian) - expected).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_TRUE(laplacian.isCompressed());
  EXPECT_EQ(laplacian.nonZeros(), 4 + 2 * 5); // the diagonal and five distinct pairs
  for (int column = 0; column < 4; ++column)  // rows increasing, each once
    for (int k = laplacian.outerIndexPtr()[column] + 1; k < laplacian.outerIndexPtr()[column + 1];
         ++k)
      EXPECT_LT(laplacian.innerIndexPtr()[k - 1], laplacian.innerIndexPtr()[k]);
}

} // namespace
} // namespace meromorph
