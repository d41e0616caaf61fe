// Every map the suite makes, judged from the files `meromorph param` wrote, by code of the test's
// own (written_map.h): no folded face anywhere (branch vertices included), the local degree of
// every vertex as written equals the `branch` property and the report's branch points, the degree
// is 1 / 2 / 2g - 2, Riemann-Hurwitz holds and each layer covers the sphere once.
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "mesh/validation.h"
#include "test_support.h"
#include "written_map.h"

namespace meromorph {
namespace {

using test::run_cli;

// A torus as modelling tools make it: a grid of quads, each split along the same diagonal, so
// every vertex has two right-angled corners.
std::string quad_split_torus(const test::TempDir &dir, int major, int minor, double r) {
  std::ostringstream text;
  text.precision(17);
  text << "OFF\n" << major * minor << " " << 2 * major * minor << " 0\n";
  for (int i = 0; i < major; ++i)
    for (int j = 0; j < minor; ++j) {
      const double u = 2 * M_PI * i / major, v = 2 * M_PI * j / minor;
      text << (1 + r * std::cos(v)) * std::cos(u) << " " << (1 + r * std::cos(v)) * std::sin(u)
           << " " << r * std::sin(v) << "\n";
    }
  for (int i = 0; i < major; ++i)
    for (int j = 0; j < minor; ++j) {
      const int a = i * minor + j, b = ((i + 1) % major) * minor + j;
      const int c = ((i + 1) % major) * minor + (j + 1) % minor, d = i * minor + (j + 1) % minor;
      text << "3 " << a << " " << b << " " << c << "\n3 " << a << " " << c << " " << d << "\n";
    }
  return dir.write("quad_torus_" + std::to_string(major) + ".off", text.str());
}

// What the report says about branching is what the written map does: the same branch vertices,
// each with the local degree its one-ring's image winds.
void expect_reported_branching(const nlohmann::json &report, const test::WrittenMap &map,
                               const std::string &name) {
  std::set<int> reported;
  for (const auto &b : report["branch_points"]) {
    // Where non-manifold spots were split, the sphere file has its own numbering.
    const int vertex = b.value("sphere_vertex", b["vertex"].get<int>());
    reported.insert(vertex);
    EXPECT_EQ(b["local_degree"], map.local_degree[size_t(vertex)]) << name;
    EXPECT_EQ(b["ramification"], b["local_degree"]) << name << ": the old key, kept one release";
  }
  EXPECT_EQ(reported, std::set<int>(map.branch_vertices.begin(), map.branch_vertices.end()))
      << name;
}

// Returns the written map's mean angle error in degrees (infinity if there is no map).
double expect_valid_written_map(const test::TempDir &dir, const std::string &input, int genus,
                                double max_angle_error_degrees = INFINITY) {
  const std::string name = input.substr(input.rfind('/') + 1);
  const test::RunResult r =
      run_cli({"param", input, "-o", dir.path(name + ".uv.ply"), "--sphere",
               dir.path(name + ".sphere.ply"), "--report", dir.path(name + ".json"), "--quiet"});
  EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
  if (r.exit_code != 0) return INFINITY;
  std::ifstream report_stream(dir.path(name + ".json"));
  const nlohmann::json report = nlohmann::json::parse(report_stream);
  const int euler = 2 - 2 * genus;
  const test::WrittenMap map = test::read_written_map(dir.path(name + ".sphere.ply"), euler);
  const int degree = genus == 0 ? 1 : genus == 1 ? 2 : 2 * genus - 2;

  EXPECT_EQ(map.folded_faces.size(), 0u)
      << name << ": folded faces, first " << (map.folded_faces.empty() ? -1 : map.folded_faces[0]);
  EXPECT_EQ(map.degree, degree) << name << ": area " << map.area_over_4pi << " x 4 pi";
  EXPECT_TRUE(map.riemann_hurwitz) << name << ": ramification " << map.ramification;
  EXPECT_EQ(report["degree"], map.degree) << name;
  EXPECT_EQ(report["genus"], genus) << name;
  expect_reported_branching(report, map, name);
  int wrong_branch_property = 0, first_wrong = -1;
  for (int v = 0; v < map.vertices; ++v)
    if (map.branch_property[size_t(v)] !=
        (map.local_degree[size_t(v)] >= 2 ? map.local_degree[size_t(v)] : 0)) {
      ++wrong_branch_property;
      if (first_wrong < 0) first_wrong = v;
    }
  EXPECT_EQ(wrong_branch_property, 0) << name << ": first at vertex " << first_wrong;
  EXPECT_EQ(int(map.layer_coverage.size()), degree) << name;
  // Each layer covers the sphere once, up to the faces along the cuts (where the images are
  // large, one face is a few percent of the sphere).
  for (size_t k = 0; k < map.layer_coverage.size(); ++k)
    EXPECT_NEAR(map.layer_coverage[k], 1.0, 0.02 + map.layer_cut_area[k])
        << name << ": layer " << k << ", along its cuts " << map.layer_cut_area[k];
  const double angle_error = test::written_angle_error_degrees(map, dir.path(name + ".uv.ply"));
  EXPECT_LT(angle_error, max_angle_error_degrees) << name;
  EXPECT_NEAR(angle_error,
              report["distortion"]["overall"]["angle_error_mean_degrees"].get<double>(), 1e-3)
      << name;
  return angle_error;
}

TEST(WrittenMaps, SharedMeshes) {
  test::TempDir dir;
  for (const auto &[name, genus] :
       std::vector<std::pair<const char *, int>>{{"sphere.off", 0},
                                                 {"maxplanck.nf25k.off", 0},
                                                 {"torus.off", 1},
                                                 {"knot.obj", 1},
                                                 {"kitten.nf20k.off", 1},
                                                 {"kitten.nv40k.off", 1},
                                                 {"eight.off", 2}})
    expect_valid_written_map(dir, test::data_path(name), genus);
}

TEST(WrittenMaps, NoisyMeshesMapValidly) {
  // Shared meshes with Gaussian noise of 0.2 mean edge lengths on every vertex (obtuse corners
  // everywhere, as scans have). The kitten: a face beside a branch vertex folds until its region
  // is re-embedded (fold_untangling.h); the torus: until the rings around that branch vertex's
  // star are re-embedded about its value (branch_star.h). The eight: every vertex near one critical
  // point has a corner above 100 degrees, so the star placed there folds the faces beyond it until
  // they are re-embedded about the branch value (branch_star.h). Judged from the written files.
  test::TempDir dir;
  expect_valid_written_map(dir, test::data_path("kitten.nf20k.noisy.off"), 1);
  expect_valid_written_map(dir, test::data_path("torus.noisy.off"), 1);
  expect_valid_written_map(dir, test::data_path("eight.noisy.off"), 2);
}

// Genus 0 at least as conformal as FLASH (Choi, Lam, Lui 2015), the best linear method, on the
// shared meshes and on generated obtuse ones (raw marching cubes, needles down to 0.1 degrees):
// the bounds are FLASH's mean angle errors on the same files, measured once with
// scripts/compare_flash.sh's FLASH (its published code in Octave) and this suite's judge of the
// written sphere (FLASH folds 3 to 15 faces on four of them; the judge asks for none here).
TEST(WrittenMaps, GenusZeroAsConformalAsTheBestLinearMethod) {
  test::TempDir dir;
  expect_valid_written_map(dir, test::data_path("sphere.off"), 0, 0.31);
  expect_valid_written_map(dir, test::data_path("maxplanck.nf25k.off"), 0, 1.18);
  for (const auto &[arguments, bound] : std::vector<std::pair<std::vector<std::string>, double>>{
           {{"sphere", "-s", "3"}, 0.27},
           {{"blob", "--tentacles", "4", "--length", "2"}, 1.67},
           {{"blob", "--tentacles", "6", "--length", "3", "--needles", "0.5"}, 3.33},
           {{"genus", "-g", "0", "--resolution", "16", "--raw-marching-cubes", "--needles", "0.1"},
            1.03},
           {{"genus", "-g", "0", "--resolution", "16", "--raw-marching-cubes", "--needles", "0.5"},
            0.88},
           {{"genus", "-g", "0", "--resolution", "24", "--raw-marching-cubes"}, 1.66},
           {{"genus", "-g", "0", "--resolution", "30", "--raw-marching-cubes", "--needles", "0.3"},
            0.50},
           {{"genus", "-g", "0", "--resolution", "40", "--raw-marching-cubes"}, 0.52},
           {{"genus", "-g", "0", "--resolution", "40", "--raw-marching-cubes", "--needles", "0.1"},
            1.02}}) {
    std::vector<std::string> make = {"make"};
    make.insert(make.end(), arguments.begin(), arguments.end());
    std::string name;
    for (const std::string &argument : arguments)
      name += argument;
    const std::string path = dir.path(name + ".ply");
    make.insert(make.end(), {"-o", path});
    ASSERT_EQ(run_cli(make).exit_code, 0);
    expect_valid_written_map(dir, path, 0, bound);
  }
}

// The same surface as text OFF, as PLY with single-precision coordinates and as OBJ: the same
// pole and the same map up to the input's rounding. The surface is subdivided flat (200k
// vertices), so that many faces have nearly the same shape: its PLY copy once got another pole
// than the OFF (as a 200k-vertex dragon did), and another map.
TEST(WrittenMaps, TheSameMapFromOffPlyAndObj) {
  test::TempDir dir;
  const std::string off = dir.path("maxplanck16.off");
  ASSERT_EQ(
      run_cli({"make", "subdivide", test::data_path("maxplanck.nf25k.off"), "-s", "2", "-o", off})
          .exit_code,
      0);
  std::vector<std::array<double, 3>> positions;
  std::vector<std::array<int, 3>> triangles;
  test::arrays_of(off, positions, triangles);
  const std::string ply = dir.path("maxplanck16.ply"), obj = dir.path("maxplanck16.obj");
  {
    std::ofstream out(ply, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex " << positions.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
        << triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const auto &p : positions)
      for (double x : p) {
        const float single = float(x);
        out.write(reinterpret_cast<const char *>(&single), sizeof single);
      }
    for (const auto &t : triangles) {
      const unsigned char three = 3;
      out.write(reinterpret_cast<const char *>(&three), 1);
      out.write(reinterpret_cast<const char *>(t.data()), 3 * sizeof(int));
    }
  }
  {
    std::ofstream out(obj);
    out.precision(17);
    for (const auto &p : positions)
      out << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
    for (const auto &t : triangles)
      out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  }
  std::vector<test::WrittenMap> maps;
  std::vector<int> poles;
  for (const std::string &input : {off, ply, obj}) {
    expect_valid_written_map(dir, input, 0);
    const std::string name = input.substr(input.rfind('/') + 1);
    maps.push_back(test::read_written_map(dir.path(name + ".sphere.ply"), 2));
    std::ifstream report_stream(dir.path(name + ".json"));
    poles.push_back(nlohmann::json::parse(report_stream)["genus0"]["pole_face"].get<int>());
  }
  for (size_t k = 1; k < maps.size(); ++k) {
    EXPECT_EQ(poles[k], poles[0]) << "input " << k;
    ASSERT_EQ(maps[k].sphere.size(), maps[0].sphere.size());
    double farthest = 0;
    for (size_t v = 0; v < maps[0].sphere.size(); ++v)
      for (int i = 0; i < 3; ++i)
        farthest = std::max(farthest, std::abs(maps[k].sphere[v][i] - maps[0].sphere[v][i]));
    EXPECT_LT(farthest, 1e-3) << "input " << k;
  }
}

TEST(WrittenMaps, QuadSplitTori) {
  test::TempDir dir;
  for (const auto &[major, minor, r] : std::vector<std::tuple<int, int, double>>{
           {48, 16, 0.25}, {48, 12, 0.25}, {32, 16, 0.5}, {64, 24, 0.4}})
    expect_valid_written_map(dir, quad_split_torus(dir, major, minor, r), 1);
}

TEST(WrittenMaps, GeneratedSurfaces) {
  test::TempDir dir;
  struct Made {
    std::vector<std::string> arguments;
    int genus;
  };
  for (const Made &made : std::vector<Made>{
           {{"sphere", "-s", "3"}, 0},
           {{"blob", "--tentacles", "4", "--length", "2"}, 0},
           {{"torus", "--method", "grid", "--resolution", "24"}, 1},
           {{"torus", "--method", "implicit", "--resolution", "32"}, 1},
           {{"genus", "-g", "2", "--resolution", "30"}, 2},
           {{"genus", "-g", "3", "--resolution", "30"}, 3},
           {{"genus", "-g", "4", "--resolution", "30"}, 4},
           // Needles as scans and exporters leave them, and raw marching cubes.
           {{"sphere", "-s", "3", "--needles", "0.5"}, 0},
           {{"torus", "--method", "grid", "--resolution", "24", "--needles", "0.5"}, 1},
           {{"torus", "--method", "implicit", "--resolution", "32", "--raw-marching-cubes"}, 1},
           {{"genus", "-g", "2", "--resolution", "30", "--needles", "0.5"}, 2},
           {{"genus", "-g", "3", "--resolution", "30", "--needles", "0.5"}, 3},
           {{"genus", "-g", "2", "--resolution", "30", "--raw-marching-cubes"}, 2},
           // Both at once: slivers whose images turn over inside their stars (fold_untangling.h
           // puts such a vertex into its star's kernel).
           {{"genus", "-g", "6", "--resolution", "28", "--raw-marching-cubes", "--needles", "0.3"},
            6}}) {
    std::string name = "made";
    for (const std::string &a : made.arguments)
      name += "_" + a;
    std::vector<std::string> arguments = {"make"};
    arguments.insert(arguments.end(), made.arguments.begin(), made.arguments.end());
    arguments.insert(arguments.end(), {"-o", dir.path(name + ".ply")});
    const test::RunResult r = run_cli(arguments);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_valid_written_map(dir, dir.path(name + ".ply"), made.genus);
  }
}

TEST(WrittenMaps, PoorTriangulationsMapAsConformallyAsRemeshedOnes) {
  // The same surface three ways: isotropically remeshed, raw marching cubes (needles down to
  // 0.1 degrees, caps near 180) and remeshed with needles injected. Each written map is a valid
  // branched cover, and the poor ones distort angles about as little as the clean one.
  test::TempDir dir;
  for (int genus : {3, 4, 5, 6}) {
    const std::string stem = dir.path("genus" + std::to_string(genus));
    const std::vector<std::string> make = {"make",         "genus", "-g", std::to_string(genus),
                                           "--resolution", "30"};
    auto made = [&](const std::string &suffix, std::vector<std::string> extra) {
      std::vector<std::string> arguments = make;
      arguments.insert(arguments.end(), extra.begin(), extra.end());
      arguments.insert(arguments.end(), {"-o", stem + suffix + ".ply"});
      const test::RunResult r = run_cli(arguments);
      EXPECT_EQ(r.exit_code, 0) << r.err;
      return stem + suffix + ".ply";
    };
    const double clean = expect_valid_written_map(dir, made("", {}), genus);
    const double raw = expect_valid_written_map(dir, made("raw", {"--raw-marching-cubes"}), genus);
    const double needles =
        expect_valid_written_map(dir, made("needles", {"--needles", "0.3"}), genus);
    EXPECT_LT(raw, 1.15 * clean) << "genus " << genus << ": raw marching cubes " << raw
                                 << " degrees, remeshed " << clean;
    EXPECT_LT(needles, 1.15 * clean)
        << "genus " << genus << ": needles " << needles << " degrees, remeshed " << clean;
  }
}

TEST(WrittenMaps, CadPartsMapValidly) {
  // Parts as CAD programs export them (make cad: flat faces fanned into long thin triangles,
  // walls as strips; a thin plate has corners down to 0.06 degrees), as STL: where their own
  // triangles cannot carry the map, it is computed on them subdivided and written with the
  // vertices it needs added. Judged from the written files.
  test::TempDir dir;
  for (const char *thickness : {"0.05", "0.001"}) {
    const std::string input = dir.path(std::string("plate") + thickness + ".stl");
    const test::RunResult made = run_cli(
        {"make", "cad", "--holes", "1", "--segments", "64", "--thickness", thickness, "-o", input});
    ASSERT_EQ(made.exit_code, 0) << made.err;
    expect_valid_written_map(dir, input, 1);
  }
}

// `make genus` of this genus and edges per ring, marching cubes' triangles kept and needles
// injected (30% of the edges split near one end); its path.
std::string raw_marching_cubes_with_needles(const test::TempDir &dir, int genus, int resolution) {
  const std::string path = dir.path("genus" + std::to_string(genus) + "_raw_needles.ply");
  const test::RunResult made =
      run_cli({"make", "genus", "-g", std::to_string(genus), "--resolution",
               std::to_string(resolution), "--raw-marching-cubes", "--needles", "0.3", "-o", path});
  EXPECT_EQ(made.exit_code, 0) << made.err;
  return path;
}

TEST(WrittenMaps, SliverFoldsDoNotCostMorePairs) {
  // Raw marching cubes with needles injected (genus 3, 15k vertices): the first pair's snapped
  // map fails Riemann-Hurwitz only at sliver faces whose images are turned over. Untangling them
  // (as the written map's would) makes it a valid cover: it is kept without solving and snapping
  // the five other pairs (1.9 s before, 0.3 s with it).
  test::TempDir dir;
  const std::string input = raw_marching_cubes_with_needles(dir, 3, 40);
  expect_valid_written_map(dir, input, 3);
  std::ifstream report_stream(input + ".json");
  const nlohmann::json report = nlohmann::json::parse(report_stream);
  EXPECT_EQ(report["pair_attempts"], 1);
  EXPECT_GT(report["untangled_vertices"].get<int>(), 0);
}

TEST(WrittenMaps, TheSameInputWritesTheSameFiles) {
  // Raw marching cubes with needles, genus 7 (20k vertices): branch snapping and fold
  // untangling re-embed many stars here, over both cores. (A fixed vertex left without a chart
  // position once read uninitialised memory: one run in three to six differed, and some failed.)
  test::TempDir dir;
  const std::string input = raw_marching_cubes_with_needles(dir, 7, 28);
  expect_valid_written_map(dir, input, 7);
  const std::string first = test::file_bytes(input + ".sphere.ply");
  for (int run = 0; run < 3; ++run) {
    const test::RunResult again = run_cli({"param", input, "-o", dir.path("again.uv.ply"),
                                           "--sphere", dir.path("again.sphere.ply"), "--quiet"});
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_TRUE(test::file_bytes(dir.path("again.sphere.ply")) == first) << "run " << run;
  }
}

// Meshes as users bring them: holes closed for the computation, several parts. Judged from the
// files: every input vertex and face is there, in order; no face is folded; every vertex away from
// a hole winds as the report says; each part covers the sphere `degree` times (less its holes'
// gaps), and closed parts satisfy Riemann-Hurwitz on their own.
struct PartExpected {
  int genus;
  bool has_holes;
  double largest_gap = 0.5; // of the sphere's area / 4 pi, with holes
};

void expect_valid_parts_map(const test::TempDir &dir, const std::string &input,
                            const std::vector<std::string> &options,
                            const std::vector<PartExpected> &parts,
                            bool split_vertices_expected = false) {
  const std::string name = input.substr(input.rfind('/') + 1);
  std::vector<std::string> arguments = {"param",    input,
                                        "-o",       dir.path(name + ".uv.ply"),
                                        "--sphere", dir.path(name + ".sphere.ply"),
                                        "--report", dir.path(name + ".json"),
                                        "--quiet"};
  arguments.insert(arguments.end(), options.begin(), options.end());
  const test::RunResult r = run_cli(arguments);
  ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
  std::ifstream report_stream(dir.path(name + ".json"));
  const nlohmann::json report = nlohmann::json::parse(report_stream);
  const test::WrittenMap map = test::read_written_map(dir.path(name + ".sphere.ply"), 0,
                                                      report.value("component_spacing", 0.0));
  Mesh original;
  test::load(input, original);
  // Every input face is there, in order, on the input's vertices; the sphere file has the input's
  // vertices in order, then (non-manifold spots split) copies of some, each with its source.
  EXPECT_EQ(map.faces, original.FN()) << name;
  if (split_vertices_expected)
    EXPECT_GT(map.vertices, original.VN()) << name;
  else
    EXPECT_EQ(map.vertices, original.VN()) << name;
  for (int v = 0; v < map.vertices; ++v)
    ASSERT_EQ(map.source_vertex[size_t(v)], v < original.VN() ? v : map.source_vertex[size_t(v)])
        << name;
  for (int v = original.VN(); v < map.vertices; ++v)
    ASSERT_TRUE(map.source_vertex[size_t(v)] >= 0 && map.source_vertex[size_t(v)] < original.VN())
        << name << ": vertex " << v;
  for (int f = 0; f < map.faces; ++f)
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(map.source_vertex[size_t(map.triangles[size_t(f)][size_t(k)])],
                index_of(original, original.face[size_t(f)].cV(k)))
          << name << ": face " << f;
  // The sphere is a 2-manifold: no edge with more than two faces, one fan of faces per vertex.
  std::map<std::array<int, 2>, int> faces_on_edge;
  std::vector<std::vector<std::array<int, 2>>> link(size_t(map.vertices));
  for (const auto &t : map.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[size_t(k)], b = t[size_t((k + 1) % 3)], c = t[size_t((k + 2) % 3)];
      ++faces_on_edge[{std::min(a, b), std::max(a, b)}];
      link[size_t(a)].push_back({b, c});
    }
  for (const auto &[edge, count] : faces_on_edge)
    ASSERT_LE(count, 2) << name << ": sphere edge " << edge[0] << "-" << edge[1];
  for (int v = 0; v < map.vertices; ++v) {
    // The link's edges b -> c chain into one path or cycle.
    std::map<int, int> next;
    std::set<int> starts;
    for (const auto &[b, c] : link[size_t(v)]) {
      next[b] = c;
      starts.insert(b);
    }
    for (const auto &[b, c] : link[size_t(v)])
      starts.erase(c);
    if (link[size_t(v)].empty()) continue;
    const int start = starts.empty() ? link[size_t(v)].front()[0] : *starts.begin();
    std::set<int> visited;
    for (int at = start; next.count(at) && visited.insert(at).second;)
      at = next[at];
    ASSERT_EQ(visited.size(), link[size_t(v)].size())
        << name << ": sphere vertex " << v << " has " << link[size_t(v)].size()
        << " faces in pieces";
  }
  EXPECT_EQ(map.folded_faces.size(), 0u)
      << name << ": folded faces, first " << (map.folded_faces.empty() ? -1 : map.folded_faces[0]);
  expect_reported_branching(report, map, name);
  ASSERT_EQ(map.component_area_over_4pi.size(), parts.size()) << name;
  ASSERT_EQ(report["components"].size(), parts.size()) << name;
  for (size_t k = 0; k < parts.size(); ++k) {
    const int genus = parts[k].genus;
    const int degree = genus == 0 ? 1 : genus == 1 ? 2 : 2 * genus - 2;
    EXPECT_EQ(report["components"][k]["genus"], genus) << name << " part " << k;
    EXPECT_EQ(report["components"][k]["degree"], degree) << name << " part " << k;
    const double area = map.component_area_over_4pi.at(int(k));
    if (parts[k].has_holes) {
      EXPECT_LT(area, degree) << name << " part " << k << ": the holes leave gaps";
      EXPECT_GT(area, degree - parts[k].largest_gap) << name << " part " << k;
    } else {
      EXPECT_NEAR(area, degree, 0.01) << name << " part " << k;
      EXPECT_EQ(2 - 2 * genus, 2 * degree - map.component_ramification.at(int(k)))
          << name << " part " << k << ": Riemann-Hurwitz";
    }
  }
}

std::string several_parts(const test::TempDir &dir) {
  // The shared sphere, torus and "eight", side by side in one file.
  std::ostringstream vertices, faces;
  vertices.precision(17);
  int vertex_count = 0, face_count = 0, offset = 0;
  for (const char *name : {"sphere.off", "torus.off", "eight.off"}) {
    Mesh part;
    test::load(test::data_path(name), part);
    for (const MeshVertex &v : part.vert)
      vertices << v.cP()[0] + 3 * offset << " " << v.cP()[1] << " " << v.cP()[2] << "\n";
    for (const MeshFace &f : part.face)
      faces << "3 " << vertex_count + index_of(part, f.cV(0)) << " "
            << vertex_count + index_of(part, f.cV(1)) << " "
            << vertex_count + index_of(part, f.cV(2)) << "\n";
    vertex_count += part.VN();
    face_count += part.FN();
    ++offset;
  }
  return dir.write("three_parts.off", "OFF\n" + std::to_string(vertex_count) + " " +
                                          std::to_string(face_count) + " 0\n" + vertices.str() +
                                          faces.str());
}

TEST(WrittenMaps, HolesClosedAndSeveralParts) {
  test::TempDir dir;
  expect_valid_parts_map(dir, test::data_path("bunny.off"), {"--close-holes"}, {{0, true}});
  expect_valid_parts_map(dir, test::data_path("eight.hole.off"), {"--close-holes"}, {{2, true}});
  expect_valid_parts_map(dir, test::data_path("face.off"), {"--close-holes"}, {{0, true}});
  expect_valid_parts_map(dir, several_parts(dir), {"--layer-gap", "0.2"},
                         {{0, false}, {1, false}, {2, false}});
  // --pack-uv: each part's texture in its own cell of a 2 x 2 grid over the unit square.
  const std::string parts = several_parts(dir);
  const test::RunResult packed =
      run_cli({"param", parts, "-o", dir.path("packed.ply"), "--sphere", dir.path("packed.sph.ply"),
               "--report", dir.path("packed.json"), "--pack-uv", "--quiet"});
  ASSERT_EQ(packed.exit_code, 0) << packed.err;
  const auto texture = test::read_vertex_columns(dir.path("packed.ply"));
  const auto sphere = test::read_vertex_columns(dir.path("packed.sph.ply"));
  ASSERT_EQ(texture.at("texture_u").size(), sphere.at("component").size());
  for (size_t v = 0; v < sphere.at("component").size(); ++v) {
    const int part = int(sphere.at("component")[v]);
    const double u = texture.at("texture_u")[v], w = texture.at("texture_v")[v];
    ASSERT_TRUE(u >= 0.5 * (part % 2) && u <= 0.5 * (part % 2 + 1) && w >= 0.5 * (part / 2) &&
                w <= 0.5 * (part / 2 + 1))
        << "vertex " << v << " of part " << part << " at (" << u << ", " << w << ")";
  }
  EXPECT_EQ(run_cli({"param", parts, "-o", dir.path("p.ply"), "--pack-uv", "--uv", "stereographic"})
                .exit_code,
            2);
  // With --strict a mesh with holes is refused, naming the option that closes them.
  const test::RunResult refused = run_cli(
      {"param", test::data_path("bunny.off"), "-o", dir.path("b.ply"), "--strict", "--quiet"});
  EXPECT_EQ(refused.exit_code, 3);
  EXPECT_NE(refused.err.find("--close-holes"), std::string::npos) << refused.err;
}

// Meshes with non-manifold spots: two cubes sharing an edge, two copies of the shared
// sphere touching at a vertex, the shared torus with a fin (a triangle on one of its edges).

std::string cubes_sharing_an_edge(const test::TempDir &dir) {
  return dir.write("cubes_sharing_an_edge.off", test::cubes_sharing_an_edge_off());
}

std::string spheres_touching_at_a_vertex(const test::TempDir &dir) {
  std::vector<std::array<double, 3>> positions;
  std::vector<std::array<int, 3>> triangles;
  test::arrays_of(test::data_path("sphere.off"), positions, triangles);
  const int n = int(positions.size());
  auto height = [&](int v) { return positions[size_t(v)][2]; };
  int top = 0, bottom = 0;
  for (int v = 0; v < n; ++v) {
    if (height(v) > height(top)) top = v;
    if (height(v) < height(bottom)) bottom = v;
  }
  // A second sphere whose lowest vertex is the first one's highest.
  std::vector<int> copy_of(static_cast<size_t>(n));
  for (int v = 0; v < n; ++v) {
    if (v == bottom) {
      copy_of[size_t(v)] = top;
      continue;
    }
    copy_of[size_t(v)] = int(positions.size());
    auto p = positions[size_t(v)];
    for (int k = 0; k < 3; ++k)
      p[size_t(k)] += positions[size_t(top)][size_t(k)] - positions[size_t(bottom)][size_t(k)];
    positions.push_back(p);
  }
  const size_t face_count = triangles.size();
  for (size_t f = 0; f < face_count; ++f)
    triangles.push_back({copy_of[size_t(triangles[f][0])], copy_of[size_t(triangles[f][1])],
                         copy_of[size_t(triangles[f][2])]});
  return dir.write("spheres_touching_at_a_vertex.off", test::off_text(positions, triangles));
}

std::string torus_with_a_fin(const test::TempDir &dir) {
  std::vector<std::array<double, 3>> positions;
  std::vector<std::array<int, 3>> triangles;
  test::arrays_of(test::data_path("torus.off"), positions, triangles);
  const auto [a, b, c] = triangles[0];
  std::array<double, 3> apex{};
  for (int k = 0; k < 3; ++k) // above the edge a-b, on the side of c's mirror image
    apex[size_t(k)] = positions[size_t(a)][size_t(k)] + positions[size_t(b)][size_t(k)] -
                      positions[size_t(c)][size_t(k)];
  apex[2] += 0.3;
  positions.push_back(apex);
  triangles.push_back({b, a, int(positions.size()) - 1});
  return dir.write("torus_with_a_fin.off", test::off_text(positions, triangles));
}

// Zero-area faces as meshes have them: a cap at a T-junction (the midpoint of an edge joined to
// its ends, the face beside it split in two), a cap in a fan (the midpoint joined to two points
// inside the face beside it as well), a needle (a vertex doubled at the same point, joined by two
// faces of zero area).
enum class ZeroArea { cap, cap_in_a_fan, needle };

const char *zero_area_name(ZeroArea kind) {
  return kind == ZeroArea::cap ? "cap" : kind == ZeroArea::cap_in_a_fan ? "fan" : "needle";
}

// A copy of a mesh file with one zero-area face of the kind (two for a needle), at its first face.
std::string with_zero_area_faces(const test::TempDir &dir, const std::string &path, ZeroArea kind) {
  std::vector<std::array<double, 3>> positions;
  std::vector<std::array<int, 3>> triangles;
  test::arrays_of(path, positions, triangles);
  const std::string name = path.substr(path.rfind('/') + 1);
  const auto [a, b, c] = triangles[0];
  const int added = int(positions.size());
  auto mean = [&](std::initializer_list<int> of) {
    std::array<double, 3> point{0, 0, 0};
    for (int v : of)
      for (int k = 0; k < 3; ++k)
        point[size_t(k)] += positions[size_t(v)][size_t(k)] / double(of.size());
    return point;
  };
  if (kind == ZeroArea::cap) { // (a, m, c), (m, b, c) and the cap (a, b, m) against the face
    positions.push_back(mean({a, b}));
    triangles[0] = {a, added, c};
    triangles.push_back({added, b, c});
    triangles.push_back({a, b, added});
  } else if (kind == ZeroArea::cap_in_a_fan) { // m joined to e1, e2 inside (a, b, c) too
    positions.push_back(mean({a, b}));
    const int m = added, e1 = added + 1, e2 = added + 2;
    positions.push_back(mean({a, m, c}));
    positions.push_back(mean({m, b, c}));
    triangles[0] = {a, m, e1};
    for (const std::array<int, 3> &t : std::vector<std::array<int, 3>>{
             {m, e2, e1}, {m, b, e2}, {b, c, e2}, {e2, c, e1}, {e1, c, a}, {a, b, m}})
      triangles.push_back(t);
  } else { // a doubled: (n, b, c), (a, n, c); across a-b: (b, n, o), (n, a, o)
    positions.push_back(positions[size_t(a)]);
    triangles[0] = {added, b, c};
    triangles.push_back({a, added, c});
    for (size_t f = 1; f + 1 < triangles.size(); ++f)
      for (int k = 0; k < 3; ++k)
        if (triangles[f][size_t(k)] == b && triangles[f][size_t((k + 1) % 3)] == a) {
          const int o = triangles[f][size_t((k + 2) % 3)];
          triangles[f] = {b, added, o};
          triangles.push_back({added, a, o});
          f = triangles.size();
          break;
        }
  }
  return dir.write(name + "." + zero_area_name(kind) + ".off",
                   test::off_text(positions, triangles));
}

TEST(WrittenMaps, NonManifoldSpotsTakenApart) {
  test::TempDir dir;
  expect_valid_parts_map(dir, cubes_sharing_an_edge(dir), {"--split-nonmanifold"},
                         {{0, false}, {0, false}}, true);
  expect_valid_parts_map(dir, spheres_touching_at_a_vertex(dir), {"--split-nonmanifold"},
                         {{0, false}, {0, false}}, true);
  // Split and with zero-area faces taken out: the sphere file still has the input's faces, in
  // order, on the split vertices (the zero-area faces' own images are flat: see
  // ZeroAreaFacesAreKept).
  for (ZeroArea kind : {ZeroArea::cap, ZeroArea::needle}) {
    const std::string input = with_zero_area_faces(dir, spheres_touching_at_a_vertex(dir), kind);
    const test::RunResult r =
        run_cli({"param", input, "-o", dir.path("both.ply"), "--sphere",
                 dir.path("both.sphere.ply"), "--split-nonmanifold", "--quiet"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const test::WrittenMap map = test::read_written_map(dir.path("both.sphere.ply"), 0, 2.5);
    Mesh original;
    test::load(input, original);
    ASSERT_EQ(map.faces, original.FN());
    EXPECT_GT(map.vertices, original.VN());
    for (int f = 0; f < map.faces; ++f)
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(map.source_vertex[size_t(map.triangles[size_t(f)][size_t(k)])],
                  index_of(original, original.face[size_t(f)].cV(k)))
            << zero_area_name(kind) << ": face " << f;
  }
  // The fin comes off the torus as a part of its own with a hole (its three edges; closed by a
  // fan, it covers about half of its sphere).
  expect_valid_parts_map(dir, torus_with_a_fin(dir), {"--split-nonmanifold", "--close-holes"},
                         {{1, false}, {0, true, 0.75}}, true);
  std::ifstream report_stream(dir.path("torus_with_a_fin.off.json"));
  const nlohmann::json report = nlohmann::json::parse(report_stream);
  EXPECT_EQ(report["nonmanifold_split"]["edges"].size(), 1u);
  EXPECT_EQ(report["nonmanifold_split"]["vertices"].size(), 2u);
  // The fin taken off with --strict (holes not closed): refused, naming the option, and the
  // hole's vertex, a copy the split made, is said to be one.
  const test::RunResult open_fin =
      run_cli({"param", torus_with_a_fin(dir), "-o", dir.path("fin.ply"), "--split-nonmanifold",
               "--strict", "--quiet"});
  EXPECT_EQ(open_fin.exit_code, 3);
  EXPECT_NE(open_fin.err.find("--close-holes"), std::string::npos) << open_fin.err;
  EXPECT_NE(open_fin.err.find("is a copy of"), std::string::npos) << open_fin.err;
  // With --strict each is refused, naming the spot and the option; the files stay unwritten.
  for (const std::string &input : {cubes_sharing_an_edge(dir), spheres_touching_at_a_vertex(dir)}) {
    const test::RunResult refused =
        run_cli({"param", input, "-o", dir.path("refused.ply"), "--strict", "--quiet"});
    EXPECT_EQ(refused.exit_code, 3);
    EXPECT_NE(refused.err.find("--split-nonmanifold"), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find("non-manifold"), std::string::npos) << refused.err;
    EXPECT_FALSE(std::ifstream(dir.path("refused.ply")).good());
  }
}

TEST(WrittenMaps, ZeroAreaFacesAreKept) {
  // Mapped without them, written with them: every input vertex and face is in the files, and no
  // face is folded, the zero-area ones included: their images are thin but turned the right way
  // (a needle's doubled vertex and a cap's middle one moved a little off their neighbours), so
  // every vertex's one-ring winds once around it at least.
  test::TempDir dir;
  for (const auto &[name, genus] : std::vector<std::pair<std::string, int>>{
           {"sphere.off", 0}, {"torus.off", 1}, {"eight.off", 2}})
    for (ZeroArea kind : {ZeroArea::cap, ZeroArea::cap_in_a_fan, ZeroArea::needle}) {
      const std::string input = with_zero_area_faces(dir, test::data_path(name), kind);
      const std::string label = input.substr(input.rfind('/') + 1);
      const test::RunResult r = run_cli({"param", input, "-o", dir.path(label + ".uv.ply"),
                                         "--sphere", dir.path(label + ".sphere.ply"), "--report",
                                         dir.path(label + ".json"), "--quiet"});
      ASSERT_EQ(r.exit_code, 0) << label << ": " << r.err;
      Mesh original;
      test::load(input, original);
      const test::WrittenMap map =
          test::read_written_map(dir.path(label + ".sphere.ply"), 2 - 2 * genus);
      EXPECT_EQ(map.vertices, original.VN()) << label;
      EXPECT_EQ(map.faces, original.FN()) << label;
      EXPECT_EQ(map.degree, genus == 0 ? 1 : 2) << label;
      std::set<int> flat;
      for (int f = 0; f < original.FN(); ++f)
        if (has_zero_area(original.face[size_t(f)])) flat.insert(f);
      EXPECT_EQ(flat.size(), kind == ZeroArea::needle ? 2u : 1u) << label;
      EXPECT_TRUE(map.folded_faces.empty())
          << label << ": " << map.folded_faces.size() << " folded, the first "
          << map.folded_faces.front()
          << (flat.count(map.folded_faces.front()) ? " (zero area)" : "");
      for (int v = 0; v < map.vertices; ++v)
        EXPECT_GE(map.local_degree[size_t(v)], 1) << label << ": vertex " << v;
      for (int f : flat) {
        const auto &t = map.triangles[size_t(f)];
        Eigen::Vector3d p[3];
        for (int k = 0; k < 3; ++k)
          p[k] = Eigen::Vector3d(map.sphere[size_t(t[size_t(k)])][0],
                                 map.sphere[size_t(t[size_t(k)])][1],
                                 map.sphere[size_t(t[size_t(k)])][2]);
        // Near a great circle (spherically flat): the distance of the third corner from the plane
        // of the other two and the centre, against the longest side, within what the map's angle
        // error on these coarse meshes (up to 10 degrees) allows.
        double longest = 0;
        for (int k = 0; k < 3; ++k)
          longest = std::max(longest, (p[(k + 1) % 3] - p[k]).norm());
        const double off_circle =
            std::abs(p[0].dot(p[1].cross(p[2]))) / std::max(1e-300, longest * longest);
        EXPECT_LT(off_circle, 0.1)
            << label << ": the image of zero-area face " << f << " is not flat";
      }
      std::ifstream report_stream(dir.path(label + ".json"));
      const nlohmann::json report = nlohmann::json::parse(report_stream);
      EXPECT_TRUE(report["valid"].get<bool>()) << label;
      expect_reported_branching(report, map, label);
      const auto texture = test::read_vertex_columns(dir.path(label + ".uv.ply"));
      EXPECT_EQ(texture.at("texture_u").size(), size_t(original.VN())) << label;
    }
}

} // namespace
} // namespace meromorph
