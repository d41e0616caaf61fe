// The main job against exact results: degree, branch points and Riemann-Hurwitz, layers that each
// cover the sphere once, no folds away from branch points, Moebius centring, seam-correct wedges.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/errors.h"
#include "common/job_threads.h"
#include "forms/holomorphic_pipeline.h"
#include "io/mesh_reader.h"
#include "maps/genus1_map.h"
#include "maps/parameterization.h"
#include "mesh/face_vectors.h"
#include "mesh/prepared_mesh.h"
#include "shapes/generated_surfaces.h"
#include "sphere/mobius_centering.h"
#include "test_support.h"

namespace meromorph {
namespace {

void expect_valid_map(const Mesh &mesh, const Parameterization &map, int degree,
                      const std::string &name) {
  EXPECT_EQ(map.degree, degree) << name;
  EXPECT_NEAR(map.area_over_4pi, degree, 0.01) << name;
  EXPECT_TRUE(map.riemann_hurwitz_ok) << name << ": ramification " << map.ramification;
  EXPECT_EQ(map.euler, 2 * map.degree - map.ramification) << name;
  EXPECT_EQ(map.sheets.count, degree) << name;
  for (double coverage : map.sheets.coverage)
    EXPECT_NEAR(coverage, 1.0, 0.025) << name;
  EXPECT_EQ(map.quality.away_from_branch_points.folded_faces, 0) << name;
  // Moebius centring: the area-weighted centroid of the image is the origin.
  EXPECT_LT(centroid(map.sphere, vertex_areas(mesh)).norm(), 1e-6) << name;
  for (const Eigen::Vector3d &p : map.sphere)
    ASSERT_NEAR(p.norm(), 1.0, 1e-9) << name;
  // Seam-correct wedges: no face spans more than half the texture, but for faces whose image is
  // itself that large (a chord above 1: where a zero and a pole of the ratio fall within a face
  // or two, which the mesh does not resolve), and those are rare.
  int around_pole = 0, crowded = 0;
  for (size_t f = 0; f < map.uv.wedge.size(); ++f) {
    const auto &wedge = map.uv.wedge[f];
    if (map.uv.around_pole[f]) { // the faces whose image holds a pole (a few per layer)
      ++around_pole;
      continue;
    }
    double chord = 0;
    for (int k = 0; k < 3; ++k)
      chord = std::max(chord, (map.sphere[index_of(mesh, mesh.face[f].cV(k))] -
                               map.sphere[index_of(mesh, mesh.face[f].cV((k + 1) % 3))])
                                  .norm());
    if (chord > 1.0) {
      ++crowded;
      continue;
    }
    double low_u = 9, high_u = -9, low_v = 9, high_v = -9;
    for (const auto &uv : wedge) {
      low_u = std::min(low_u, uv[0]);
      high_u = std::max(high_u, uv[0]);
      low_v = std::min(low_v, uv[1]);
      high_v = std::max(high_v, uv[1]);
    }
    ASSERT_LE(high_u - low_u, 0.5) << name;
    ASSERT_LE(high_v - low_v, 0.5) << name;
  }
  EXPECT_LE(around_pole, 2 * degree + 2) << name;
  EXPECT_LE(crowded, int(mesh.face.size()) / 100) << name;
}

TEST(Parameterization, ClosedSharedMeshes) {
  // The angle error bound guards against losing conformality (measured values plus about 30%).
  struct Case {
    const char *name;
    int genus, degree, branch_points;
    double angle_error_degrees;
  };
  for (const Case &c : {Case{"sphere.off", 0, 1, 0, 0.5}, Case{"maxplanck.nf25k.off", 0, 1, 0, 1.5},
                        Case{"torus.off", 1, 2, 4, 8.5}, Case{"knot.obj", 1, 2, 4, 14},
                        Case{"kitten.nf20k.off", 1, 2, 4, 2.6},
                        Case{"kitten.nv40k.off", 1, 2, 4, 1.3}, Case{"eight.off", 2, 2, 6, 12.5}}) {
    Mesh mesh;
    test::load(test::data_path(c.name), mesh);
    const Parameterization map = parameterize(mesh);
    EXPECT_EQ(map.genus, c.genus) << c.name;
    expect_valid_map(mesh, map, c.degree, c.name);
    EXPECT_EQ(int(map.branch_points.size()), c.branch_points) << c.name;
    EXPECT_LT(map.quality.overall.angle_error_mean_degrees, c.angle_error_degrees) << c.name;
    for (const BranchPoint &b : map.branch_points)
      EXPECT_EQ(b.local_degree, 2) << c.name;
  }
}

TEST(Parameterization, GeneratedSurfacesOfGenusZeroToTwo) {
  Mesh sphere, torus, implicit_torus, genus2;
  make_genus_surface(sphere, 0, 24);
  make_grid_torus(torus, 2.0, 1.0, 64, 32);
  make_implicit_torus(implicit_torus, 2.0, 1.0, 24);
  make_genus_surface(genus2, 2, 30);
  expect_valid_map(sphere, parameterize(sphere), 1, "genus 0");
  expect_valid_map(torus, parameterize(torus), 2, "grid torus");
  expect_valid_map(implicit_torus, parameterize(implicit_torus), 2, "implicit torus");
  const Parameterization map = parameterize(genus2);
  expect_valid_map(genus2, map, 2, "genus 2");
  EXPECT_EQ(map.branch_points.size(), 6u) << "genus 2: 2g + 2 branch points";
}

// A generated chain of `genus` handles, mapped with the default pair: a valid map of degree
// 2g - 2 with 6g - 6 branch points counted with multiplicity (Riemann-Hurwitz).
Parameterization expect_higher_genus_map(int genus, int resolution, const std::string &name) {
  Mesh mesh;
  make_genus_surface(mesh, genus, resolution);
  Parameterization map = parameterize(mesh);
  expect_valid_map(mesh, map, 2 * genus - 2, name);
  EXPECT_EQ(map.ramification, 6 * genus - 6) << name;
  return map;
}

TEST(Parameterization, GeneratedSurfacesOfGenusThreeToFive) {
  // The default (generic) pair: degree 2g - 2 and, by Riemann-Hurwitz, 6g - 6 branch points
  // counted with multiplicity; each of the 2g - 2 layers covers the sphere once.
  for (int genus : {3, 4, 5}) {
    const std::string name = "genus " + std::to_string(genus);
    const Parameterization map = expect_higher_genus_map(genus, 30, name);
    ASSERT_EQ(map.form_coefficients.first.size(), genus) << name;
    ASSERT_EQ(map.form_coefficients.second.size(), genus) << name;
    EXPECT_GE(map.pair_attempts, 1) << name;
  }
}

TEST(Parameterization, CoarseHigherGenusTriesTheNextGenericPair) {
  // At 20 edges across a ring some pairs crowd below what the mesh resolves; the next pair of
  // the fixed list is taken, and the result is still exact in degree and branching.
  int most_attempts = 0;
  for (int genus : {3, 4}) {
    const Parameterization map =
        expect_higher_genus_map(genus, 20, "coarse genus " + std::to_string(genus));
    most_attempts = std::max(most_attempts, map.pair_attempts);
  }
  EXPECT_GT(most_attempts, 1) << "these meshes exercise the retry";
}

TEST(Parameterization, ChosenFormPair) {
  Mesh mesh;
  make_genus_surface(mesh, 3, 24);
  ParameterizeOptions options;
  options.form_pair = {0, 2};
  const Parameterization map = parameterize(mesh, options);
  EXPECT_EQ(map.pair_attempts, 1) << "a chosen pair is used as it is";
  EXPECT_EQ(map.form_coefficients.first, Eigen::Vector3cd(1, 0, 0));
  EXPECT_EQ(map.form_coefficients.second, Eigen::Vector3cd(0, 0, 1));
  options.form_pair = {1, 1};
  EXPECT_THROW(parameterize(mesh, options), ArgumentError);
}

TEST(Parameterization, GenusZeroWithLongThinPartsFoldsNothing) {
  // Tentacles of radius 0.12 out of a ball of radius 1, reaching 2.6 (7.2 times longer than
  // thick, from the ball's surface; peers fold dozens of faces here) and 4.0 (13 times: their
  // tips shrink to about 1e-14 on the sphere).
  struct Case {
    int tentacles;
    double length;
  };
  for (const Case &c : {Case{4, 2.6}, Case{6, 2.6}, Case{8, 2.6}, Case{4, 4.0}, Case{6, 4.0}}) {
    Mesh mesh;
    make_tentacle_blob(mesh, c.tentacles, c.length, 30);
    const Parameterization map = parameterize(mesh);
    const std::string name =
        std::to_string(c.tentacles) + " tentacles of length " + std::to_string(c.length);
    expect_valid_map(mesh, map, 1, name);
    EXPECT_EQ(map.quality.overall.folded_faces, 0) << name;
    EXPECT_EQ(map.raised_weights, 0) << name << ": the cotangent weights as they are";
  }
}

// Each parallel region wakes the team, and on a machine with other work its threads wait for a
// core: a 12k-vertex genus-0 map once took 3.6-5 s where 0.3 s of work was done, its Moebius
// centring spread over 266 short regions of milliseconds each. Counted over the whole map of a
// 12.5k-vertex mesh with a team of two (146 regions before loops of cheap items and short sums
// ran serially below 16k items and 4 chunks).
TEST(Parameterization, GenusZeroOpensFewParallelRegions) {
  Mesh mesh;
  test::load(test::data_path("maxplanck.nf25k.off"), mesh);
  const JobThreads team(2);
  const long before = parallel_regions_opened();
  const Parameterization map = parameterize(mesh);
  EXPECT_TRUE(map.valid);
  EXPECT_LT(parallel_regions_opened() - before, 60);
}

TEST(Parameterization, GenusOneWithLongLimbsIsMappedOrRefusedWithTheCause) {
  // A ball of radius 1 with a hole and four limbs of radius 0.12 (lengths below: from the ball's
  // surface to the tip, over the diameter): reaching 4.4 (14.7 times longer than thick, as long
  // as genus 0 maps, test above) the map is valid; reaching 5.8 (20 times) the limbs' tips shrink
  // to about e^-40 of the body, which no point on the sphere in doubles resolves, and the map is
  // refused, saying so, instead of written broken: exit code 3 and nothing written, unless asked
  // to keep it.
  for (const double length : {2.0, 4.4}) {
    Mesh mesh;
    make_tentacle_blob(mesh, 4, length, 30, true);
    const Parameterization map = parameterize(mesh);
    const std::string name = "limbs of length " + std::to_string(length);
    expect_valid_map(mesh, map, 2, name);
    EXPECT_TRUE(map.valid) << name;
    // The double pole sits where the flat metric is largest: never on a limb.
    const Point3 &origin = mesh.vert[size_t(map.origin_vertex)].cP();
    EXPECT_LT(origin.Norm(), 1.2) << name;
  }

  test::TempDir dir;
  const test::RunResult made = test::run_cli({"make", "blob", "--hole", "--tentacles", "4",
                                              "--length", "5.8", "-o", dir.path("limbs.ply")});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  const test::RunResult refused =
      test::run_cli({"param", dir.path("limbs.ply"), "-o", dir.path("limbs.uv.ply"), "--quiet"});
  EXPECT_EQ(refused.exit_code, 3) << refused.err;
  EXPECT_NE(refused.err.find("faces shrink below what double precision resolves"),
            std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("no valid map on this triangulation"), std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("smaller than double precision resolves"), std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("the first at"), std::string::npos) << "where: " << refused.err;
  EXPECT_NE(refused.err.find("nothing was written"), std::string::npos) << refused.err;
  // Windings around faces below what doubles resolve cannot be measured: no claim of branch
  // points missed.
  EXPECT_EQ(refused.err.find("branch points were missed"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path("limbs.uv.ply")));
  // Unless asked to keep it: written, still exit 3, and the report says why.
  const test::RunResult kept =
      test::run_cli({"param", dir.path("limbs.ply"), "-o", dir.path("limbs.uv.ply"), "--report",
                     dir.path("limbs.json"), "--quiet", "--keep-invalid"});
  EXPECT_EQ(kept.exit_code, 3) << kept.err;
  ASSERT_TRUE(std::filesystem::exists(dir.path("limbs.json")));
  std::ifstream kept_report_stream(dir.path("limbs.json"));
  const nlohmann::json kept_report = nlohmann::json::parse(kept_report_stream);
  EXPECT_FALSE(kept_report["valid"].get<bool>());
  EXPECT_FALSE(kept_report["invalid"].empty());
  ASSERT_TRUE(kept_report.contains("advice"));
  // The report gives each cause with its remedy as a code; the CLI words it with what to do.
  ASSERT_FALSE(kept_report["advice"].empty());
  EXPECT_EQ(kept_report["advice"][0]["remedy"], "shorten_thin_parts") << kept_report["advice"];
  EXPECT_NE(kept_report["advice"][0]["cause"].get<std::string>().find("long thin parts"),
            std::string::npos);
  EXPECT_NE(refused.err.find("shorten or thicken them"), std::string::npos) << refused.err;
}

TEST(Parameterization, SolidAnglesOfTinyTrianglesKeepTheirSign) {
  // Three points 1e-10 apart on the unit sphere: the triple product in differences resolves
  // their orientation (the plain product errs by about 1e-16, more than their area of 1e-20).
  const Eigen::Vector3d a = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  const Eigen::Vector3d e1 = a.cross(Eigen::Vector3d::UnitX()).normalized(), e2 = a.cross(e1);
  const Eigen::Vector3d b = (a + 1e-10 * e1).normalized(), c = (a + 1e-10 * e2).normalized();
  const double area = signed_solid_angle(a, b, c);
  EXPECT_NEAR(area, 0.5e-20, 0.05e-20);
  EXPECT_NEAR(signed_solid_angle(a, c, b), -area, 0.05e-20);
  EXPECT_FALSE(folded_image(a, b, c));
  EXPECT_TRUE(folded_image(a, c, b));
}

// The shortcut that settles "the solid angle is above a threshold" without an arctangent never
// says so wrongly, and settles most triangles: random triangles of every size from 1e-9 to
// half the sphere, either orientation, flat ones and ones past a hemisphere, at the thresholds
// the fold and flatness tests ask (0 and 1e-9 of the longest chord squared).
TEST(Parameterization, SolidAngleShortcutAgreesWithTheArctangent) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto point = [&] {
    return Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
  };
  int settled = 0, tried = 0;
  for (int k = 0; k < 200000; ++k) {
    const Eigen::Vector3d a = point();
    const double size = std::pow(10.0, -9.0 * std::abs(unit(random)));
    const Eigen::Vector3d b = (a + size * point()).normalized();
    Eigen::Vector3d c = (a + size * point()).normalized();
    if (k % 10 == 0) c = (a + 0.37 * (b - a)).normalized(); // flat to rounding
    const double chord =
        std::max({(a - b).squaredNorm(), (b - c).squaredNorm(), (c - a).squaredNorm()});
    for (const double threshold : {0.0, 1e-9 * chord}) {
      ++tried;
      if (!solid_angle_clearly_above(a, b, c, threshold)) continue;
      ++settled;
      ASSERT_GT(signed_solid_angle(a, b, c), threshold) << k << " " << size;
    }
  }
  EXPECT_GT(settled, tried / 3); // about half the triangles turn the right way
}

TEST(Parameterization, GenusZeroConvergesToConformalUnderRefinement) {
  double previous = 1e9;
  for (int subdivisions : {2, 3, 4}) {
    Mesh mesh;
    make_icosphere(mesh, subdivisions);
    const Parameterization map = parameterize(mesh);
    expect_valid_map(mesh, map, 1, "icosphere");
    const double error = map.quality.overall.angle_error_mean_degrees;
    EXPECT_LT(error, 0.7 * previous) << subdivisions;
    previous = error;
  }
}

TEST(Parameterization, TorusBranchPointsSitAtTheHalfPeriods) {
  Mesh mesh;
  make_grid_torus(mesh, 2.0, 1.0, 64, 32);
  const Parameterization map = parameterize(mesh);
  ASSERT_EQ(map.branch_points.size(), 4u);
  const HolomorphicForms forms = compute_holomorphic_forms(mesh);
  const Genus1Map flat = genus1_map(prepare_mesh(mesh), forms.normalized[0], Complex(1, 0),
                                    forms.riemann_matrix(0, 0), map.origin_vertex);
  double longest_edge = 0;
  for (int e = 0; e < int(forms.normalized[0].size()); ++e)
    longest_edge = std::max(longest_edge, std::abs(forms.normalized[0][e]));
  // Each half period and the origin have a branch vertex within one ring.
  std::vector<Complex> targets{Complex(0, 0)};
  for (const Complex &h : flat.p_function.half_periods())
    targets.push_back(h);
  for (const Complex &target : targets) {
    double nearest = 1e9;
    for (const BranchPoint &b : map.branch_points)
      nearest = std::min(nearest, flat.p_function.lattice_distance(flat.flat[b.vertex] - target));
    EXPECT_LE(nearest, 1.01 * longest_edge) << target;
  }
}

TEST(Parameterization, ThinToriHaveTwoLayers) {
  // A thin torus has its branch values in two close pairs at opposite points of the sphere; on a
  // coarse grid the cuts between a pair are only a face or two wide, and must still separate the
  // two sheets.
  struct Case {
    double major, minor;
    int resolution;
  };
  for (const Case &c : {Case{3, 1, 24}, Case{5, 1, 20}, Case{8, 1, 20}}) {
    Mesh mesh;
    make_grid_torus(mesh, c.major, c.minor, int(std::lround(c.resolution * c.major / c.minor)),
                    c.resolution);
    const std::string name = "R " + std::to_string(c.major) + " r " + std::to_string(c.minor);
    expect_valid_map(mesh, parameterize(mesh), 2, name);
  }
}

TEST(Parameterization, WithoutMoebiusTheCentroidIsLeftAlone) {
  Mesh mesh;
  make_grid_torus(mesh, 2.0, 1.0, 64, 32);
  ParameterizeOptions options;
  options.mobius = false;
  const Parameterization map = parameterize(mesh, options);
  EXPECT_FALSE(map.mobius_applied);
  EXPECT_GT(centroid(map.sphere, vertex_areas(mesh)).norm(), 1e-3);
  EXPECT_EQ(map.degree, 2);
}

TEST(Parameterization, RefusesWhatValidationRefuses) {
  for (const char *name : {"eight.hole.off", "face.off", "bunny.off"}) {
    Mesh mesh;
    test::load(test::data_path(name), mesh);
    EXPECT_THROW(parameterize(mesh), InputError) << name;
  }
  Mesh mesh;
  make_grid_torus(mesh, 2.0, 1.0, 20, 10);
  ParameterizeOptions options;
  options.origin_vertex = 100000;
  EXPECT_THROW(parameterize(mesh, options), ArgumentError);
}

TEST(ParamCommand, WritesSurfaceSphereAndReport) {
  test::TempDir dir;
  const std::string input = test::data_path("eight.off");
  const test::RunResult r =
      test::run_cli({"param", input, "-o", dir.path("out.ply"), "--sphere", dir.path("sphere.ply"),
                     "--report", dir.path("report.json"), "--layer-gap", "0.25", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream report_stream(dir.path("report.json"));
  const nlohmann::json report = nlohmann::json::parse(report_stream);
  EXPECT_EQ(report["genus"], 2);
  EXPECT_EQ(report["degree"], 2);
  EXPECT_TRUE(report["riemann_hurwitz_ok"].get<bool>());
  EXPECT_EQ(report["branch_points"].size(), 6u);
  EXPECT_TRUE(report["valid"].get<bool>());
  EXPECT_TRUE(report["invalid"].empty());
  EXPECT_FALSE(report.contains("advice")) << "advice only when the map is not valid";
  for (const char *key : {"euler", "method", "mobius", "distortion", "repairs", "timings_ms",
                          "version", "riemann_matrix"})
    EXPECT_TRUE(report.contains(key)) << key;

  // The surface keeps the input's vertices; the sphere file adds layer and branch.
  Mesh surface, layered;
  test::load(dir.path("out.ply"), surface);
  test::load(dir.path("sphere.ply"), layered);
  EXPECT_EQ(surface.VN(), 766);
  EXPECT_EQ(layered.VN(), 766);
  std::ifstream sphere_stream(dir.path("sphere.ply"), std::ios::binary);
  std::string header;
  for (std::string line; std::getline(sphere_stream, line) && line != "end_header";)
    header += line + "\n";
  EXPECT_NE(header.find("property int layer"), std::string::npos) << header;
  EXPECT_NE(header.find("property uchar branch"), std::string::npos) << header;
  double largest = 0;
  for (const MeshVertex &v : layered.vert)
    largest = std::max(largest, v.cP().Norm());
  EXPECT_NEAR(largest, 1.25, 1e-6) << "layer 1 on the sphere of radius 1 + gap";

  // Raw marching cubes of genus 3 (needles down to 0.1 degrees) map as the remeshed surface does.
  const test::RunResult made =
      test::run_cli({"make", "genus", "-g", "3", "--resolution", "30", "-o", dir.path("g3.ply")});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  const test::RunResult generic =
      test::run_cli({"param", dir.path("g3.ply"), "-o", dir.path("g3.uv.ply"), "--quiet"});
  EXPECT_EQ(generic.exit_code, 0) << generic.err;
  const test::RunResult raw = test::run_cli({"make", "genus", "-g", "3", "--resolution", "30",
                                             "--raw-marching-cubes", "-o", dir.path("raw3.ply")});
  ASSERT_EQ(raw.exit_code, 0) << raw.err;
  const test::RunResult raw_mapped =
      test::run_cli({"param", dir.path("raw3.ply"), "-o", dir.path("raw3.uv.ply"), "--quiet"});
  EXPECT_EQ(raw_mapped.exit_code, 0) << raw_mapped.err;

  // Never over the input; open surfaces refused with exit code 3 under --strict.
  EXPECT_EQ(test::run_cli({"param", input, "-o", input}).exit_code, 2);
  const test::RunResult open = test::run_cli(
      {"param", test::data_path("eight.open.off"), "-o", dir.path("x.ply"), "--strict"});
  EXPECT_EQ(open.exit_code, 3);
  EXPECT_NE(open.err.find("boundary loop"), std::string::npos) << open.err;
}

} // namespace
} // namespace meromorph
