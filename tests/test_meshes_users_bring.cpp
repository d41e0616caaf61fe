// Meshes as users bring them, mapped with the defaults: seam duplicates, doubled faces, vertices
// on no face, triangle strips, quads that share three vertices. The map is computed on the
// surface without those defects, so what is written for the input's own vertices must be the
// map of the clean surface to the bit, and the extra vertices and faces must carry their twins'
// values; the clean map itself is judged by the suite's own reader (written_map.h).
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/mesh_reader.h"
#include "mesh/mesh_from_arrays.h"
#include "test_support.h"
#include "written_map.h"

namespace meromorph {
namespace {

using Positions = std::vector<std::array<double, 3>>;
using Triangles = std::vector<std::array<int, 3>>;

// A torus as a grid of `major` x `minor` quads, each split along the same diagonal.
void grid_torus(int major, int minor, Positions &positions, Triangles &triangles) {
  for (int i = 0; i < major; ++i)
    for (int j = 0; j < minor; ++j) {
      const double u = 2 * M_PI * i / major, v = 2 * M_PI * j / minor;
      positions.push_back({(1 + 0.4 * std::cos(v)) * std::cos(u),
                           (1 + 0.4 * std::cos(v)) * std::sin(u), 0.4 * std::sin(v)});
    }
  for (int i = 0; i < major; ++i)
    for (int j = 0; j < minor; ++j) {
      const int a = i * minor + j, b = ((i + 1) % major) * minor + j;
      const int c = ((i + 1) % major) * minor + (j + 1) % minor, d = i * minor + (j + 1) % minor;
      triangles.push_back({a, b, c});
      triangles.push_back({a, c, d});
    }
}

struct Written {
  test::WrittenMesh surface, sphere;
};

Written map_with_defaults(const test::TempDir &dir, const std::string &input) {
  const std::string name = input.substr(input.rfind('/') + 1);
  const test::RunResult r = test::run_cli({"param", input, "-o", dir.path(name + ".uv.ply"),
                                           "--sphere", dir.path(name + ".sphere.ply"), "--report",
                                           dir.path(name + ".json"), "--quiet"});
  EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
  if (r.exit_code != 0) return {};
  return {test::read_written_mesh(dir.path(name + ".uv.ply"), false),
          test::read_written_mesh(dir.path(name + ".sphere.ply"))};
}

// Per-vertex values of `column` at vertex `v` of both files equal.
void expect_same_vertex(const Written &a, size_t va, const Written &b, size_t vb,
                        const std::string &what) {
  for (const char *column : {"texture_u", "texture_v"})
    EXPECT_EQ(a.surface.columns.at(column)[va], b.surface.columns.at(column)[vb])
        << what << ": " << column << " of vertex " << va << " and " << vb;
  for (const char *column : {"x", "y", "z", "layer", "branch"})
    EXPECT_EQ(a.sphere.columns.at(column)[va], b.sphere.columns.at(column)[vb])
        << what << ": sphere " << column << " of vertex " << va << " and " << vb;
}

std::string report_notes(const test::TempDir &dir, const std::string &name) {
  std::ifstream report(dir.path(name + ".json"));
  std::stringstream text;
  text << report.rdbuf();
  return text.str();
}

// The clean torus, and the same with every defect a downloaded mesh has, appended after its own
// vertices and faces: its written values are the clean torus's to the bit.
TEST(MeshesUsersBring, DefectsAreLeftOutAndTheOutputsKeepThem) {
  test::TempDir dir;
  Positions positions;
  Triangles triangles;
  grid_torus(24, 12, positions, triangles);
  const size_t n = positions.size(), m = triangles.size();
  const Written clean =
      map_with_defaults(dir, dir.write("clean.off", test::off_text(positions, triangles)));
  ASSERT_FALSE(clean.sphere.triangles.empty());
  const test::WrittenMap clean_map = test::read_written_map(dir.path("clean.off.sphere.ply"), 0);
  EXPECT_TRUE(clean_map.folded_faces.empty());
  EXPECT_EQ(clean_map.degree, 2);
  EXPECT_TRUE(clean_map.riemann_hurwitz);

  // A seam: the faces of the first ring of quads refer to copies of the ring's vertices (as an
  // exporter splits vertices along a texture seam), which sit at the same positions.
  Positions seam_positions = positions;
  Triangles seam_triangles = triangles;
  std::map<int, int> copy_of;
  for (int j = 0; j < 12; ++j) {
    copy_of[j] = int(seam_positions.size());
    seam_positions.push_back(positions[size_t(j)]);
  }
  for (size_t f = 0; f < 2 * 12; ++f) // the quads between ring 0 and ring 1
    for (int &corner : seam_triangles[f])
      if (copy_of.count(corner)) corner = copy_of[corner];
  // A vertex on no face, and two faces written twice (one the other way round).
  seam_positions.push_back({5, 5, 5});
  seam_triangles.push_back(triangles[100]);
  seam_triangles.push_back({triangles[7][0], triangles[7][2], triangles[7][1]});
  const Written defects = map_with_defaults(
      dir, dir.write("defects.off", test::off_text(seam_positions, seam_triangles)));
  ASSERT_EQ(defects.sphere.triangles.size(), m + 2) << "every input face is written";
  ASSERT_EQ(defects.surface.columns.at("x").size(), n + 13) << "every input vertex is written";
  for (size_t v = 0; v < n; ++v)
    expect_same_vertex(defects, v, clean, v, "the torus's own vertex");
  for (const auto &[original, copy] : copy_of)
    expect_same_vertex(defects, size_t(copy), clean, size_t(original), "a seam copy");
  // The faces are the input's, in order, on the input's vertices.
  for (size_t f = 0; f < m + 2; ++f)
    EXPECT_EQ(defects.sphere.triangles[f], seam_triangles[f]) << "face " << f;
  // The vertex on no face: at the north pole of layer 0.
  EXPECT_EQ(defects.sphere.columns.at("z")[n + 12], 1.0);
  EXPECT_EQ(defects.sphere.columns.at("layer")[n + 12], 0.0);
  const std::string notes = report_notes(dir, "defects.off");
  for (const char *said :
       {"12 seam duplicate vertices welded", "2 doubled faces", "1 vertex on no face"})
    EXPECT_NE(notes.find(said), std::string::npos) << said << " in " << notes;

  // --strict refuses it, naming the first problem.
  const test::RunResult strict = test::run_cli(
      {"param", dir.path("defects.off"), "-o", dir.path("strict.ply"), "--strict", "--quiet"});
  EXPECT_EQ(strict.exit_code, 3) << strict.err;
  EXPECT_FALSE(std::ifstream(dir.path("strict.ply")).good());
}

// The torus written as a PLY of triangle strips (one per ring of quads, as stripifiers write
// them): read as the same surface and mapped validly.
// `remesh` with the defaults on the same defects (a seam of 12 duplicate vertices, a face written
// twice and one written the other way round, a vertex on no face): the safe repairs come first,
// so the written remesh is a closed torus (every side on two faces, Euler characteristic 0) and
// the report lists the repairs.
TEST(MeshesUsersBring, RemeshTakesSeamsAndDoubledFaces) {
  test::TempDir dir;
  Positions positions;
  Triangles triangles;
  grid_torus(24, 12, positions, triangles);
  std::map<int, int> copy_of;
  const size_t n = positions.size();
  for (int j = 0; j < 12; ++j) {
    copy_of[j] = int(positions.size());
    positions.push_back(positions[size_t(j)]);
  }
  for (size_t f = 0; f < 2 * 12; ++f)
    for (int &corner : triangles[f])
      if (copy_of.count(corner)) corner = copy_of[corner];
  positions.push_back({5, 5, 5});
  triangles.push_back(triangles[100]);
  triangles.push_back({triangles[7][0], triangles[7][2], triangles[7][1]});
  const std::string input = dir.write("defects.off", test::off_text(positions, triangles));
  const test::RunResult run = test::run_cli({"remesh", input, "-o", dir.path("remeshed.ply"),
                                             "--report", dir.path("remeshed.json"), "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const test::WrittenMesh remesh = test::read_written_mesh(dir.path("remeshed.ply"));
  std::map<std::pair<int, int>, int> sides;
  for (const auto &t : remesh.triangles)
    for (int k = 0; k < 3; ++k)
      ++sides[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  for (const auto &[side, faces] : sides)
    EXPECT_EQ(faces, 2) << side.first << "-" << side.second;
  EXPECT_EQ(int(remesh.columns.at("x").size()) - int(sides.size()) + int(remesh.triangles.size()),
            0);
  EXPECT_NEAR(double(remesh.columns.at("x").size()), double(n), 0.15 * double(n));
  std::ifstream stream(dir.path("remeshed.json"));
  const nlohmann::json report = nlohmann::json::parse(stream);
  const std::string repairs = report.at("repairs").dump();
  for (const char *said : {"12 duplicate vertices", "2 doubled faces", "1 vertex"})
    EXPECT_NE(repairs.find(said), std::string::npos) << said << " in " << repairs;
}

TEST(MeshesUsersBring, TriangleStripsAreRead) {
  test::TempDir dir;
  Positions positions;
  Triangles triangles;
  const int major = 24, minor = 12;
  grid_torus(major, minor, positions, triangles);
  std::vector<int> strips;
  for (int i = 0; i < major; ++i) {
    for (int j = 0; j <= minor; ++j) {
      strips.push_back(i * minor + j % minor);
      strips.push_back(((i + 1) % major) * minor + j % minor);
    }
    strips.push_back(-1);
  }
  std::ostringstream ply;
  ply.precision(17);
  ply << "ply\nformat ascii 1.0\nelement vertex " << positions.size()
      << "\nproperty float x\nproperty float y\nproperty float z\n"
      << "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
  for (const auto &p : positions)
    ply << p[0] << " " << p[1] << " " << p[2] << "\n";
  ply << strips.size();
  for (int v : strips)
    ply << " " << v;
  ply << "\n";
  const std::string path = dir.write("strips.ply", ply.str());
  Mesh mesh;
  read_mesh(path, mesh);
  const MeshArrays arrays = arrays_from_mesh(mesh);
  ASSERT_EQ(arrays.triangles.size(), size_t(2 * major * minor));
  // Every triangle of the grid, once, turned the same way.
  std::set<std::array<int, 3>> read;
  for (auto t : arrays.triangles) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    read.insert(t);
  }
  EXPECT_EQ(read.size(), arrays.triangles.size());
  map_with_defaults(dir, path);
  const test::WrittenMap map = test::read_written_map(dir.path("strips.ply.sphere.ply"), 0);
  EXPECT_TRUE(map.folded_faces.empty());
  EXPECT_EQ(map.degree, 2);
  EXPECT_TRUE(map.riemann_hurwitz);
}

// Two quads on three shared vertices (as modelling tools write them around a pole), each split
// along the shorter diagonal, would make the same triangle twice: the second is split along the
// other.
TEST(MeshesUsersBring, QuadsSharingThreeVerticesMakeNoDoubledTriangles) {
  test::TempDir dir;
  const std::string path = dir.write("quads.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                                  "v 1.2 1.3 0.5\nf 1 2 3 4\nf 1 2 3 5\n");
  Mesh mesh;
  read_mesh(path, mesh);
  const MeshArrays arrays = arrays_from_mesh(mesh);
  ASSERT_EQ(arrays.triangles.size(), 4u);
  std::set<std::array<int, 3>> corners;
  for (auto t : arrays.triangles) {
    std::sort(t.begin(), t.end());
    corners.insert(t);
  }
  EXPECT_EQ(corners.size(), 4u);
}

// Where the file's polygons were split into triangles, a message that names triangles also names
// the file's own faces they are in.
TEST(MeshesUsersBring, MessagesNameTheFilesOwnFaces) {
  test::TempDir dir;
  const std::string path = dir.write("pyramid.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                                    "v 0.5 0.5 1\nf 1 4 3 2\nf 1 2 5\nf 2 3 5\n"
                                                    "f 3 4 5\nf 4 1 5\nf 1 2 5\n");
  const test::RunResult strict =
      test::run_cli({"param", path, "-o", dir.path("p.ply"), "--strict", "--quiet"});
  EXPECT_EQ(strict.exit_code, 3);
  EXPECT_NE(strict.err.find("faces 2 and 6 (numbered as triangles; in the file, triangle 2 is in "
                            "face 1, triangle 6 is in face 5)"),
            std::string::npos)
      << strict.err;
  const test::RunResult info = test::run_cli({"info", path, "--strict"});
  EXPECT_NE(info.out.find("triangle 6 is in face 5"), std::string::npos) << info.out;
  // By default the doubled face is left out and the pyramid mapped.
  EXPECT_EQ(test::run_cli({"param", path, "-o", dir.path("p.ply"), "--quiet"}).exit_code, 0);
}

// A CAD part as exported (make cad: a plate with a hole, its flat faces fanned into long thin
// triangles, as STL): its own triangles cannot carry the map. The written surface keeps the
// input's vertices first, unchanged and in order, then the added ones, each where the report
// says (on the input's face it names, at its barycentric coordinates); every written face lies on
// one input face; the map is a valid cover (judged by the suite's reader). With
// --no-added-vertices or --strict it is refused instead (exit 3), nothing written.
TEST(MeshesUsersBring, PoorTriangulationsGetTheVerticesTheMapNeeds) {
  test::TempDir dir;
  const std::string input = dir.path("plate.stl");
  const test::RunResult made = test::run_cli(
      {"make", "cad", "--holes", "1", "--segments", "64", "--thickness", "0.05", "-o", input});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  Mesh mesh;
  read_mesh(input, mesh);
  const MeshArrays original = arrays_from_mesh(mesh);
  const Written written = map_with_defaults(dir, input);
  ASSERT_FALSE(written.surface.columns.empty());
  std::ifstream report_stream(dir.path("plate.stl.json"));
  const nlohmann::json report = nlohmann::json::parse(report_stream);
  const auto &x = written.surface.columns.at("x"), &y = written.surface.columns.at("y"),
             &z = written.surface.columns.at("z");
  const size_t n = original.positions.size();
  ASSERT_GT(x.size(), n);
  ASSERT_EQ(report["added_vertices"].size(), x.size() - n);
  for (size_t v = 0; v < n; ++v)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ((k == 0 ? x : k == 1 ? y : z)[v], original.positions[v][k]) << "vertex " << v;
  // The written surface's vertex at (face, b1, b2) of the input.
  auto on_face = [&](int face, double b1, double b2, int k) {
    const auto &c = original.triangles[size_t(face)];
    return (1 - b1 - b2) * original.positions[size_t(c[0])][k] +
           b1 * original.positions[size_t(c[1])][k] + b2 * original.positions[size_t(c[2])][k];
  };
  for (const auto &added : report["added_vertices"]) {
    const size_t v = added["vertex"].get<size_t>();
    const int face = added["face"].get<int>();
    const double b1 = added["b1"].get<double>(), b2 = added["b2"].get<double>();
    ASSERT_TRUE(face >= 0 && size_t(face) < original.triangles.size());
    EXPECT_TRUE(b1 >= -1e-12 && b2 >= -1e-12 && b1 + b2 <= 1 + 1e-12) << v;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR((k == 0 ? x : k == 1 ? y : z)[v], on_face(face, b1, b2, k), 1e-12) << v;
  }
  // Every written face on one input face: its corners' barycentric coordinates there in [0, 1].
  auto inside = [&](size_t face, size_t v) {
    const auto &c = original.triangles[face];
    const Point3 a = original.positions[size_t(c[0])], e1 = original.positions[size_t(c[1])] - a,
                 e2 = original.positions[size_t(c[2])] - a, d = Point3(x[v], y[v], z[v]) - a;
    const double g11 = e1.dot(e1), g12 = e1.dot(e2), g22 = e2.dot(e2), det = g11 * g22 - g12 * g12;
    const double b1 = (g22 * d.dot(e1) - g12 * d.dot(e2)) / det,
                 b2 = (g11 * d.dot(e2) - g12 * d.dot(e1)) / det;
    const Point3 back = a + e1 * b1 + e2 * b2;
    return b1 >= -1e-9 && b2 >= -1e-9 && b1 + b2 <= 1 + 1e-9 && (back - d - a).Norm() < 1e-9;
  };
  const auto &faces = written.sphere.triangles;
  ASSERT_EQ(faces.size(), report["written_faces"].get<size_t>());
  for (size_t f = 0; f < faces.size(); ++f) {
    bool on_one = false;
    for (size_t g = 0; g < original.triangles.size() && !on_one; ++g)
      on_one = inside(g, size_t(faces[f][0])) && inside(g, size_t(faces[f][1])) &&
               inside(g, size_t(faces[f][2]));
    EXPECT_TRUE(on_one) << "written face " << f << " lies on no input face";
  }
  const test::WrittenMap map = test::read_written_map(dir.path("plate.stl.sphere.ply"), 0);
  EXPECT_EQ(map.folded_faces.size(), 0u);
  EXPECT_EQ(map.degree, 2);
  EXPECT_TRUE(map.riemann_hurwitz);
  for (const char *refuse : {"--no-added-vertices", "--strict"}) {
    const test::RunResult r =
        test::run_cli({"param", input, "-o", dir.path("refused.ply"), refuse, "--quiet"});
    EXPECT_EQ(r.exit_code, 3) << refuse << ": " << r.err;
    EXPECT_FALSE(std::ifstream(dir.path("refused.ply")).good()) << refuse;
    // The advice is the one that works: not to refine by hand (meromorph did), but to let it add
    // the vertices.
    EXPECT_NE(r.err.find("add the vertices the map needs"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("refine it"), std::string::npos) << r.err;
  }
}

} // namespace
} // namespace meromorph
