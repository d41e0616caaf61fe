// Genus and boundary of real meshes and of generated surfaces of genus 0..8.
#include <numeric>

#include <gtest/gtest.h>

#include "mesh/topology.h"
#include "mesh/validation.h"
#include "shapes/generated_surfaces.h"
#include "test_support.h"

namespace meromorph {
namespace {

// Every finding's message, one per line, for a failing assertion to show.
std::string findings_text(const Validation &validation) {
  std::string text;
  for (const Finding &f : validation.findings)
    text += "  - " + f.message + "\n";
  return text;
}

TEST(Topology, ClosedSharedMeshes) {
  const std::pair<const char *, int> meshes[] = {
      {"sphere.off", 0},       {"maxplanck.nf25k.off", 0}, {"torus.off", 1}, {"knot.obj", 1},
      {"kitten.nf20k.off", 1}, {"kitten.nv40k.off", 1},    {"eight.off", 2},
  };
  for (const auto &[name, genus] : meshes) {
    Mesh mesh;
    test::load(test::data_path(name), mesh);
    const Topology topology = compute_topology(mesh);
    EXPECT_TRUE(topology.closed_manifold()) << name;
    EXPECT_EQ(topology.euler, 2 - 2 * genus) << name;
    EXPECT_EQ(topology.genus, genus) << name;
    EXPECT_TRUE(validate_mesh(mesh).ok()) << name << ":\n" << findings_text(validate_mesh(mesh));
  }
}

TEST(Topology, OpenSharedMeshesAreRefusedNamingTheirBoundaryLoops) {
  // Boundary edges as counted by an independent reader (shared/meshes/README.md).
  const std::pair<const char *, int> meshes[] = {
      {"eight.hole.off", 6}, {"eight.open.off", 96}, {"bunny.off", 223}, {"face.off", 358}};
  for (const auto &[name, boundary_edges] : meshes) {
    Mesh mesh;
    test::load(test::data_path(name), mesh);
    const Validation validation = validate_mesh(mesh);
    const Finding *open = validation.find(FindingKind::boundary_loops);
    ASSERT_NE(open, nullptr) << name;
    EXPECT_EQ(std::accumulate(open->sizes.begin(), open->sizes.end(), 0), boundary_edges) << name;

    // Refused with --strict, naming the loops; by default they are closed for the computation.
    const test::RunResult cli = test::run_cli({"info", test::data_path(name), "--strict"});
    EXPECT_EQ(cli.exit_code, 3) << name;
    EXPECT_NE(cli.err.find("boundary loop"), std::string::npos) << name << ": " << cli.err;
    const test::RunResult by_default = test::run_cli({"info", test::data_path(name)});
    EXPECT_EQ(by_default.exit_code, 0) << name << ": " << by_default.err;
    EXPECT_NE(by_default.out.find("meromorph param closes these for the computation"),
              std::string::npos)
        << name << ": " << by_default.out;
  }
}

TEST(Topology, GeneratedSurfacesOfGenusZeroToEight) {
  for (int genus = 0; genus <= 8; ++genus) {
    Mesh mesh;
    make_genus_surface(mesh, genus, 20);
    const Topology topology = compute_topology(mesh);
    EXPECT_EQ(topology.genus, genus);
    EXPECT_EQ(topology.euler, 2 - 2 * genus);
    EXPECT_TRUE(validate_mesh(mesh).ok()) << "genus " << genus << ":\n"
                                          << findings_text(validate_mesh(mesh));
  }
}

TEST(Topology, RawMarchingCubesSurfacesAreValidToo) {
  for (int genus : {2, 3}) {
    Mesh mesh;
    make_genus_surface(mesh, genus, 24, false);
    EXPECT_EQ(compute_topology(mesh).genus, genus);
    const Validation validation = validate_mesh(mesh);
    EXPECT_TRUE(validation.ok()) << findings_text(validation);
  }
}

TEST(Topology, GenusOfAnOpenSurfaceCountsItsHoles) {
  Mesh mesh;
  test::load(test::data_path("eight.hole.off"), mesh);
  const Topology topology = compute_topology(mesh);
  EXPECT_EQ(topology.boundary_loops.size(), 1u);
  EXPECT_EQ(topology.genus, 2);
  EXPECT_FALSE(topology.closed_manifold());
}

} // namespace
} // namespace meromorph
