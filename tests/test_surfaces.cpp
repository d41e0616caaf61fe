// The generated test surfaces: sizes, shape, orientation, determinism of the rigid motion.
#include <algorithm>
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include <vcg/complex/algorithms/stat.h>

#include "mesh/mesh_from_arrays.h"
#include "mesh/topology.h"
#include "mesh/validation.h"
#include "shapes/generated_surfaces.h"
#include "shapes/rigid_motion.h"

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
  EXPECT_GT(enclosed_volume(mesh), 0.0) << "faces point outward";
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
  EXPECT_GT(enclosed_volume(mesh), 0.0);
}

TEST(Surfaces, GenusSurfacesFaceOutwardAndAreDeterministic) {
  Mesh a, b;
  make_genus_surface(a, 3, 20);
  make_genus_surface(b, 3, 20);
  EXPECT_GT(enclosed_volume(a), 0.0);
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
  EXPECT_GT(enclosed_volume(moved), 0.0) << "a rotation keeps orientation";
}

TEST(Surfaces, InjectedNeedlesKeepTheSurfaceAndItsTopology) {
  Mesh mesh;
  make_grid_torus(mesh, 2.0, 1.0, 48, 24);
  const int before = int(mesh.vert.size());
  std::vector<Point3> original;
  for (const MeshVertex &v : mesh.vert)
    original.push_back(v.cP());
  inject_needles(mesh, 0.5);
  const Topology topology = compute_topology(mesh);
  EXPECT_TRUE(validate_mesh(mesh).ok());
  ASSERT_TRUE(topology.genus);
  EXPECT_EQ(*topology.genus, 1);
  EXPECT_GT(int(mesh.vert.size()), before + 100);
  // The first vertices are the original ones, where they were.
  for (int v = 0; v < before; ++v)
    ASSERT_EQ(mesh.vert[size_t(v)].cP(), original[size_t(v)]) << v;
  // Every new vertex lies on a segment between two original vertices (the same surface), very
  // close to one end, so the smallest angle falls below 0.1 degrees.
  double smallest = M_PI;
  for (const MeshFace &face : mesh.face)
    for (int k = 0; k < 3; ++k) {
      const Point3 u = face.cP((k + 1) % 3) - face.cP(k), w = face.cP((k + 2) % 3) - face.cP(k);
      smallest = std::min(smallest, std::atan2((u ^ w).Norm(), u * w));
    }
  EXPECT_LT(smallest * 180 / M_PI, 0.1);
  std::vector<std::set<int>> neighbours(mesh.vert.size());
  for (const MeshFace &face : mesh.face)
    for (int k = 0; k < 3; ++k)
      neighbours[size_t(index_of(mesh, face.cV(k)))].insert(index_of(mesh, face.cV((k + 1) % 3)));
  for (size_t v = size_t(before); v < mesh.vert.size(); ++v) {
    const Point3 &p = mesh.vert[v].cP();
    double nearest = 1e300;
    for (int a : neighbours[v])
      for (int b : neighbours[v]) {
        if (a >= before || b >= before || a == b) continue;
        const Point3 ab = original[size_t(b)] - original[size_t(a)];
        const double t = ((p - original[size_t(a)]) * ab) / ab.SquaredNorm();
        if (t > 0 && t < 0.02)
          nearest = std::min(nearest, (original[size_t(a)] + ab * t - p).Norm());
      }
    EXPECT_LT(nearest, 1e-12) << "vertex " << v;
  }
}

} // namespace
} // namespace meromorph
