// One crafted bad mesh per validation finding: the finding, where it is, its message, the exit
// code of `meromorph info`, and what --repair does with it.
#include <gtest/gtest.h>

#include "io/mesh_reader.h"
#include "mesh/repair.h"
#include "mesh/validation.h"
#include "test_support.h"

namespace meromorph {
namespace {

using Positions = std::vector<std::array<double, 3>>;
using Triangles = std::vector<std::array<int, 3>>;

const Positions tetra_positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const Triangles tetra_faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};

struct Crafted {
  Positions positions;
  Triangles triangles;
};

Crafted tetra() {
  return {tetra_positions, tetra_faces};
}

Crafted two_tetras(const std::array<double, 3> &offset, bool share_vertex_0) {
  Crafted mesh = tetra();
  const int base = int(mesh.positions.size());
  for (const auto &p : tetra_positions)
    mesh.positions.push_back({p[0] + offset[0], p[1] + offset[1], p[2] + offset[2]});
  for (auto t : tetra_faces) {
    for (int &i : t)
      i = (share_vertex_0 && i == 0) ? 0 : i + base;
    mesh.triangles.push_back(t);
  }
  return mesh;
}

struct Checked {
  Validation validation;
  test::RunResult cli, strict_cli;
};

Checked check(const Crafted &crafted, const std::string &name) {
  test::TempDir dir;
  const std::string path =
      dir.write(name + ".off", test::off_text(crafted.positions, crafted.triangles));
  Mesh mesh;
  read_mesh(path, mesh);
  Checked result{validate_mesh(mesh), test::run_cli({"info", path}),
                 test::run_cli({"info", path, "--strict"})};
  return result;
}

bool mapped_as_it_is(FindingKind kind) {
  return kind == FindingKind::several_components || kind == FindingKind::zero_area_faces;
}

// What param deals with for the computation unless --strict: holes closed, non-manifold spots
// taken apart, seam duplicates welded, doubled faces, faces that use a vertex twice and vertices
// on no face left out.
bool dealt_with_unless_strict(FindingKind kind) {
  return kind == FindingKind::boundary_loops || kind == FindingKind::non_manifold_edges ||
         kind == FindingKind::non_manifold_vertices || kind == FindingKind::duplicate_vertices ||
         kind == FindingKind::unreferenced_vertices ||
         kind == FindingKind::repeated_vertex_in_face || kind == FindingKind::duplicate_faces;
}

// The finding of `kind` (a copy: `checked` is often a temporary), after checking that the CLI
// prints it and says what param does: maps it as it is (several parts, zero-area faces), deals
// with it unless --strict (then refuses it), or refuses it.
Finding expect_finding(const Checked &checked, FindingKind kind) {
  const Finding *finding = checked.validation.find(kind);
  EXPECT_NE(finding, nullptr) << "missing finding " << finding_code(kind);
  if (!finding) return Finding(kind);
  EXPECT_NE(checked.cli.out.find(finding->message), std::string::npos)
      << "info prints the finding: " << checked.cli.out;
  bool all_as_it_is = true, all_mapped = true;
  for (const Finding &f : checked.validation.findings) {
    all_as_it_is &= mapped_as_it_is(f.kind);
    all_mapped &= mapped_as_it_is(f.kind) || dealt_with_unless_strict(f.kind);
  }
  if (mapped_as_it_is(kind))
    EXPECT_NE(checked.cli.out.find("meromorph param maps it as it is:"), std::string::npos)
        << checked.cli.out;
  if (dealt_with_unless_strict(kind))
    EXPECT_NE(checked.cli.out.find("for the computation"), std::string::npos) << checked.cli.out;
  EXPECT_EQ(checked.cli.exit_code, all_mapped ? 0 : 3) << checked.cli.err;
  EXPECT_EQ(checked.strict_cli.exit_code, all_as_it_is ? 0 : 3) << checked.strict_cli.err;
  const test::RunResult &refusing = all_mapped ? checked.strict_cli : checked.cli;
  if (!all_as_it_is)
    EXPECT_NE(refusing.err.find("cannot be parameterized"), std::string::npos) << refusing.err;
  return *finding;
}

TEST(Validation, CleanTetrahedronHasNoFinding) {
  const Checked checked = check(tetra(), "tetra");
  EXPECT_TRUE(checked.validation.ok());
  EXPECT_EQ(checked.cli.exit_code, 0) << checked.cli.err;
}

TEST(Validation, EmptyMesh) {
  Crafted no_faces{tetra_positions, {}};
  const Finding f = expect_finding(check(no_faces, "points"), FindingKind::empty_mesh);
  EXPECT_NE(f.message.find("no faces"), std::string::npos) << f.message;
  const Finding g = expect_finding(check(Crafted{}, "nothing"), FindingKind::empty_mesh);
  EXPECT_NE(g.message.find("no vertices"), std::string::npos) << g.message;
}

TEST(Validation, NonFiniteCoordinates) {
  Crafted mesh = tetra();
  mesh.positions[2][1] = std::numeric_limits<double>::quiet_NaN();
  mesh.positions[3][0] = std::numeric_limits<double>::infinity();
  const Finding f = expect_finding(check(mesh, "nan"), FindingKind::non_finite_coordinates);
  EXPECT_EQ(f.vertices, (std::vector<int>{2, 3}));
  EXPECT_FALSE(f.repairable);
  EXPECT_NE(f.message.find("vertices 2, 3"), std::string::npos) << f.message;
}

TEST(Validation, FaceWithRepeatedVertex) {
  Crafted mesh = tetra();
  mesh.triangles.push_back({1, 1, 2});
  const Finding f = expect_finding(check(mesh, "repeated"), FindingKind::repeated_vertex_in_face);
  EXPECT_EQ(f.faces, (std::vector<int>{4}));
  EXPECT_TRUE(f.repairable);
}

TEST(Validation, ZeroAreaFace) {
  Crafted mesh = tetra();
  mesh.positions[3] = {0.5, 0, 0}; // on the edge 0-1: face (0, 1, 3) is flat
  const Checked checked = check(mesh, "flat");
  const Finding *f = checked.validation.find(FindingKind::zero_area_faces);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->faces, (std::vector<int>{1}));
  EXPECT_NE(f->message.find("zero area"), std::string::npos);
  EXPECT_NE(checked.cli.out.find("meromorph param maps it as it is:"), std::string::npos);
  // Taking the flat face out (its longest edge flipped) leaves two faces on the same three
  // vertices: param refuses that, and info, which runs param's preparation, says so.
  EXPECT_EQ(checked.cli.exit_code, 3);
  EXPECT_NE(checked.cli.err.find("after zero-area faces were taken out"), std::string::npos)
      << checked.cli.err;
}

TEST(Validation, DuplicateVertices) {
  Crafted mesh = tetra();
  mesh.positions.push_back(mesh.positions[0]); // vertex 4 = vertex 0
  mesh.triangles[3] = {4, 3, 2};
  const Checked checked = check(mesh, "duplicate");
  const Finding f = expect_finding(checked, FindingKind::duplicate_vertices);
  EXPECT_EQ(f.vertices, (std::vector<int>{4}));
  EXPECT_EQ(f.edges, (std::vector<std::array<int, 2>>{{0, 4}}));
  EXPECT_NE(f.message.find("4 = 0"), std::string::npos) << f.message;
  EXPECT_NE(checked.validation.find(FindingKind::boundary_loops), nullptr);
}

TEST(Validation, UnreferencedVertices) {
  Crafted mesh = tetra();
  mesh.positions.push_back({5, 5, 5});
  mesh.positions.push_back({6, 5, 5});
  const Finding f = expect_finding(check(mesh, "unused"), FindingKind::unreferenced_vertices);
  EXPECT_EQ(f.vertices, (std::vector<int>{4, 5}));
  EXPECT_NE(f.message.find("vertices 4, 5"), std::string::npos) << f.message;
}

TEST(Validation, NonManifoldEdge) {
  Crafted mesh = tetra();
  mesh.positions.push_back({0.5, -1, 0.5});
  mesh.triangles.push_back({0, 1, 4}); // a fin on edge 0-1
  const Finding f = expect_finding(check(mesh, "fin"), FindingKind::non_manifold_edges);
  EXPECT_EQ(f.edges, (std::vector<std::array<int, 2>>{{0, 1}}));
  EXPECT_EQ(f.sizes, (std::vector<int>{3}));
  EXPECT_NE(f.message.find("0-1 (3 faces)"), std::string::npos) << f.message;
  EXPECT_FALSE(f.repairable);
}

TEST(Validation, NonManifoldVertex) {
  const Checked checked = check(two_tetras({-1, -1, -1}, true), "bowtie");
  const Finding f = expect_finding(checked, FindingKind::non_manifold_vertices);
  EXPECT_EQ(f.vertices, (std::vector<int>{0}));
  EXPECT_NE(checked.validation.find(FindingKind::several_components), nullptr);
}

TEST(Validation, BoundaryLoops) {
  Crafted mesh = tetra();
  mesh.triangles.pop_back();
  const Checked checked = check(mesh, "open");
  const Finding f = expect_finding(checked, FindingKind::boundary_loops);
  EXPECT_EQ(f.sizes, (std::vector<int>{3}));
  EXPECT_NE(f.message.find("1 boundary loop (hole) of 3 edges"), std::string::npos) << f.message;
  EXPECT_NE(checked.strict_cli.err.find("boundary loop"), std::string::npos)
      << checked.strict_cli.err;
}

TEST(Validation, SeveralComponents) {
  const Finding &f =
      expect_finding(check(two_tetras({3, 0, 0}, false), "two"), FindingKind::several_components);
  EXPECT_EQ(f.sizes, (std::vector<int>{4, 4}));
  EXPECT_NE(f.message.find("2 separate parts"), std::string::npos) << f.message;
}

TEST(Validation, InconsistentOrientation) {
  Crafted mesh = tetra();
  std::swap(mesh.triangles[2][0], mesh.triangles[2][1]);
  const Finding f = expect_finding(check(mesh, "flipped"), FindingKind::inconsistent_orientation);
  EXPECT_EQ(f.edges.size(), 3u);
  EXPECT_TRUE(f.repairable);
}

TEST(Validation, NonOrientableProjectivePlane) {
  // The six-vertex real projective plane (half an icosahedron, antipodes identified).
  Crafted rp2;
  for (int i = 0; i < 6; ++i)
    rp2.positions.push_back({std::cos(i * 1.1), std::sin(i * 1.7), 0.3 * i * i - i});
  rp2.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 1},
                   {1, 2, 4}, {2, 3, 5}, {3, 4, 1}, {4, 5, 2}, {5, 1, 3}};
  const Checked checked = check(rp2, "rp2");
  const Finding f = expect_finding(checked, FindingKind::non_orientable);
  EXPECT_FALSE(f.repairable);
  EXPECT_EQ(checked.validation.find(FindingKind::boundary_loops), nullptr);
  EXPECT_EQ(checked.validation.find(FindingKind::non_manifold_edges), nullptr);
}

TEST(Repair, FixesWhatIsSafeAndSaysWhat) {
  Crafted mesh = tetra();
  // Inconsistent orientation, and the first face is the odd one out: orienting coherently from it
  // would face inward, so the repair must also turn the whole surface outward.
  std::swap(mesh.triangles[0][0], mesh.triangles[0][1]);
  mesh.positions.push_back({9, 9, 9}); // unreferenced vertex 4
  mesh.triangles.push_back({3, 3, 1}); // repeated vertex
  test::TempDir dir;
  const std::string path = dir.write("fixable.off", test::off_text(mesh.positions, mesh.triangles));

  Mesh loaded;
  read_mesh(path, loaded);
  ASSERT_TRUE(validate_mesh(loaded).all_repairable());
  const std::vector<std::string> repairs = repair_mesh(loaded);
  EXPECT_EQ(repairs.size(), 3u);
  EXPECT_TRUE(validate_mesh(loaded).ok());
  EXPECT_EQ(loaded.VN(), 4);
  EXPECT_EQ(loaded.FN(), 4);

  const test::RunResult without = test::run_cli({"info", path});
  EXPECT_EQ(without.exit_code, 3);
  EXPECT_NE(without.out.find("run again with --repair"), std::string::npos) << without.out;
  const test::RunResult with = test::run_cli({"info", "--repair", path});
  EXPECT_EQ(with.exit_code, 0) << with.err;
  EXPECT_NE(with.out.find("repaired: oriented all faces consistently, facing outward"),
            std::string::npos)
      << with.out;
}

TEST(Repair, MergesDuplicatesAndClosesTheSeam) {
  Crafted mesh = tetra();
  mesh.positions.push_back(mesh.positions[0]);
  mesh.triangles[3] = {4, 3, 2};
  test::TempDir dir;
  Mesh loaded;
  read_mesh(dir.write("seam.off", test::off_text(mesh.positions, mesh.triangles)), loaded);
  EXPECT_FALSE(validate_mesh(loaded).ok());
  repair_mesh(loaded);
  EXPECT_TRUE(validate_mesh(loaded).ok());
}

} // namespace
} // namespace meromorph
