// The generated test surfaces: sizes, shape, orientation, determinism of the rigid motion.
#include <gtest/gtest.h>

#include <vcg/complex/algorithms/stat.h>

#include "mesh_from_arrays.h"
#include "rigid_motion.h"
#include "test_surfaces.h"
#include "topology.h"
#include "validation.h"

namespace meromorph {
namespace {

TEST(Surfaces, IcosphereSizesAndRadius) {
  for (int s = 0; s <= 4; ++s) {
    Mesh mesh;
    make_icosphere(mesh, s, 2.5);
    EXPECT_EQ(mesh.VN(), 10 * (1 << (2 * s)) + 2);
    EXPECT_EQ(compute_topology(mesh).genus, 0);
    for (const MeshVertex &v : mesh.vert)
      EXPECT_NEAR(v.cP().Norm(), 2.5, 1e-12);
  }
}

TEST(Surfaces, GridTorusLiesOnTheTorusOfRevolution) {
  Mesh mesh;
  make_grid_torus(mesh, 3.0, 1.0, 60, 20);
  EXPECT_EQ(mesh.VN(), 1200);
  EXPECT_EQ(compute_topology(mesh).genus, 1);
  EXPECT_TRUE(validate_mesh(mesh).ok());
  for (const MeshVertex &v : mesh.vert) {
    const Point3 &p = v.cP();
    const double radial = std::hypot(p[0], p[1]) - 3.0;
    EXPECT_NEAR(std::hypot(radial, p[2]), 1.0, 1e-12);
  }
  EXPECT_GT(vcg::tri::Stat<Mesh>::ComputeMeshVolume(mesh), 0.0) << "faces point outward";
}

TEST(Surfaces, ImplicitTorusIsCloseToTheTorusOfRevolution) {
  Mesh mesh;
  make_implicit_torus(mesh, 2.0, 1.0, 24);
  EXPECT_EQ(compute_topology(mesh).genus, 1);
  EXPECT_TRUE(validate_mesh(mesh).ok());
  double worst = 0;
  for (const MeshVertex &v : mesh.vert) {
    const Point3 &p = v.cP();
    worst = std::max(worst, std::abs(std::hypot(std::hypot(p[0], p[1]) - 2.0, p[2]) - 1.0));
  }
  EXPECT_LT(worst, 0.02); // within a small fraction of the edge length (2 pi / 24 = 0.26)
  EXPECT_GT(vcg::tri::Stat<Mesh>::ComputeMeshVolume(mesh), 0.0);
}

TEST(Surfaces, GenusSurfacesFaceOutwardAndAreDeterministic) {
  Mesh a, b;
  make_genus_surface(a, 3, 20);
  make_genus_surface(b, 3, 20);
  EXPECT_GT(vcg::tri::Stat<Mesh>::ComputeMeshVolume(a), 0.0);
  const MeshArrays first = arrays_from_mesh(a), second = arrays_from_mesh(b);
  EXPECT_EQ(first.triangles, second.triangles);
  ASSERT_EQ(first.positions.size(), second.positions.size());
  for (size_t v = 0; v < first.positions.size(); ++v)
    ASSERT_EQ(first.positions[v], second.positions[v]);
}

TEST(Surfaces, RigidMotionIsRigidAndReproducible) {
  const Similarity m1 = random_rigid_motion(42), m2 = random_rigid_motion(42),
                   m3 = random_rigid_motion(43);
  EXPECT_TRUE(m1.rotation.isApprox(m2.rotation, 0.0));
  EXPECT_FALSE(m1.rotation.isApprox(m3.rotation, 1e-6));
  EXPECT_NEAR((m1.rotation.transpose() * m1.rotation - Eigen::Matrix3d::Identity()).norm(), 0.0,
              1e-12);
  EXPECT_NEAR(m1.rotation.determinant(), 1.0, 1e-12);

  Mesh mesh, moved;
  make_grid_torus(mesh, 2.0, 1.0, 20, 10);
  make_grid_torus(moved, 2.0, 1.0, 20, 10);
  apply_similarity(m1, moved);
  for (const MeshFace &f : mesh.face) {
    const MeshFace &g = moved.face[index_of(mesh, &f)];
    EXPECT_NEAR((f.cP(0) - f.cP(1)).Norm(), (g.cP(0) - g.cP(1)).Norm(), 1e-12);
  }
  EXPECT_GT(vcg::tri::Stat<Mesh>::ComputeMeshVolume(moved), 0.0) << "a rotation keeps orientation";
}

} // namespace
} // namespace meromorph
