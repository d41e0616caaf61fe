// `meromorph match`, judged from the files it wrote with the tests' own code: the same surface
// re-triangulated (flat subdivision, half of the new inner edges flipped: the same flat faces
// cut otherwise), rigidly moved and rescaled, so the true point of each source vertex is known.
// Distances relative to the target's bounding-box diagonal; turned-over faces against the true
// normals; the round trip source -> target -> source re-derived from the two written matches.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "test_support.h"
#include "vector3.h"
#include "written_map.h"

namespace meromorph {
namespace {

using test::cross;
using test::dot;
using test::norm;
using test::sub;
using test::Vec3;

struct Surface {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> triangles;
};

struct Motion {
  double rotation[3][3];
  double scale;
  Vec3 shift;
  Vec3 operator()(const Vec3 &p) const {
    Vec3 q{};
    for (int i = 0; i < 3; ++i)
      q[size_t(i)] =
          scale * (rotation[i][0] * p[0] + rotation[i][1] * p[1] + rotation[i][2] * p[2]) +
          shift[size_t(i)];
    return q;
  }
};

Motion random_motion(unsigned seed, double scale) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> angle(0, 6.283185307179586), shift(-3, 3);
  const double a = angle(random), b = angle(random) / 2, c = angle(random);
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b),
               cc = std::cos(c), sc = std::sin(c);
  // z-y-z Euler angles
  Motion m{{{ca * cb * cc - sa * sc, -ca * cb * sc - sa * cc, ca * sb},
            {sa * cb * cc + ca * sc, -sa * cb * sc + ca * cc, sa * sb},
            {-sb * cc, sb * sc, cb}},
           scale,
           {shift(random), shift(random), shift(random)}};
  return m;
}

// Every triangle into four at its edge midpoints (the input's vertices first, keeping their
// numbers); in every other triangle the inner edge between the first two midpoints is flipped.
Surface retriangulated(const Surface &in, const Motion &motion) {
  Surface out;
  out.positions = in.positions;
  std::map<std::pair<int, int>, int> midpoint;
  const auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto found = midpoint.find(key);
    if (found != midpoint.end()) return found->second;
    const Vec3 &p = in.positions[size_t(a)], &q = in.positions[size_t(b)];
    out.positions.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
    return midpoint[key] = int(out.positions.size()) - 1;
  };
  for (size_t f = 0; f < in.triangles.size(); ++f) {
    const auto [a, b, c] = in.triangles[f];
    const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    if (f % 2 == 0)
      out.triangles.insert(out.triangles.end(),
                           {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}});
    else
      out.triangles.insert(out.triangles.end(),
                           {{a, ab, bc}, {a, bc, ca}, {ab, b, bc}, {ca, bc, c}});
  }
  for (Vec3 &p : out.positions)
    p = motion(p);
  return out;
}

Surface read_surface(const std::string &file) {
  Surface s;
  test::arrays_of(file, s.positions, s.triangles);
  return s;
}

double diagonal(const std::vector<Vec3> &p) {
  Vec3 low = p.front(), high = p.front();
  for (const Vec3 &q : p)
    for (size_t k = 0; k < 3; ++k)
      low[k] = std::min(low[k], q[k]), high[k] = std::max(high[k], q[k]);
  return norm(sub(high, low));
}

struct MatchFigures {
  double mean = 0, max = 0; // distance of matched points to the true ones / diagonal
  int turned_over = 0;      // matched triangles against the true (moved source) normal
  double landmark_max = 0;
};

// The written match of `source` onto `target` against the truth: source vertex i's true point
// is `truth[i]`; a matched triangle is turned over where its normal points against the moved
// source triangle's.
MatchFigures judged(const std::string &matched_ply, const Surface &source, const Surface &target,
                    const std::vector<Vec3> &truth, const Motion &motion) {
  const test::WrittenMesh written = test::read_written_mesh(matched_ply);
  const auto &x = written.columns.at("x"), &y = written.columns.at("y"),
             &z = written.columns.at("z"), &face = written.columns.at("target_face"),
             &b1 = written.columns.at("target_b1"), &b2 = written.columns.at("target_b2");
  EXPECT_EQ(x.size(), source.positions.size());
  EXPECT_EQ(written.triangles, source.triangles); // the source's faces, in its order
  const double d = diagonal(target.positions);
  MatchFigures figures;
  std::vector<Vec3> matched;
  for (size_t v = 0; v < x.size(); ++v) {
    matched.push_back({x[v], y[v], z[v]});
    // The written point is the target's triangle at the written weights (float precision).
    const auto &t = target.triangles.at(size_t(face[v]));
    const double w1 = b1[v], w2 = b2[v], w0 = 1 - w1 - w2;
    Vec3 at{};
    for (size_t k = 0; k < 3; ++k)
      at[k] = w0 * target.positions[size_t(t[0])][k] + w1 * target.positions[size_t(t[1])][k] +
              w2 * target.positions[size_t(t[2])][k];
    EXPECT_LT(norm(sub(at, matched.back())), 1e-5 * d) << "vertex " << v;
    const double e = norm(sub(matched.back(), truth[v])) / d;
    figures.mean += e / double(x.size());
    figures.max = std::max(figures.max, e);
  }
  for (const auto &t : source.triangles) {
    const Vec3 n = cross(sub(matched[size_t(t[1])], matched[size_t(t[0])]),
                         sub(matched[size_t(t[2])], matched[size_t(t[0])]));
    const Vec3 truth_normal =
        cross(sub(motion(source.positions[size_t(t[1])]), motion(source.positions[size_t(t[0])])),
              sub(motion(source.positions[size_t(t[2])]), motion(source.positions[size_t(t[0])])));
    figures.turned_over += dot(n, truth_normal) < 0;
  }
  return figures;
}

// Source vertex i -> its point on the target (face, weights) -> back through the target's
// vertices' written points on the source: how far from where it started / source diagonal.
std::pair<double, double> round_trip(const std::string &forward_ply,
                                     const std::string &backward_ply, const Surface &source,
                                     const Surface &target) {
  const test::WrittenMesh forward = test::read_written_mesh(forward_ply, false);
  const test::WrittenMesh backward = test::read_written_mesh(backward_ply, false);
  const double d = diagonal(source.positions);
  double mean = 0, worst = 0;
  const size_t n = source.positions.size();
  for (size_t v = 0; v < n; ++v) {
    const auto &t = target.triangles.at(size_t(forward.columns.at("target_face")[v]));
    const double w1 = forward.columns.at("target_b1")[v], w2 = forward.columns.at("target_b2")[v];
    const double w[3] = {1 - w1 - w2, w1, w2};
    Vec3 p{};
    for (int k = 0; k < 3; ++k)
      for (size_t c = 0; c < 3; ++c)
        p[c] += w[k] * backward.columns.at(c == 0 ? "x" : c == 1 ? "y" : "z")[size_t(t[size_t(k)])];
    const double e = norm(sub(p, source.positions[v])) / d;
    mean += e / double(n);
    worst = std::max(worst, e);
  }
  return {mean, worst};
}

// `match` of `source` onto its re-triangulation moved by `motion` (with --both, and the landmarks
// when given), judged against the truth: mean and largest distance, turned faces, round trip.
void expect_found_again(const test::TempDir &dir, const std::string &name, const Surface &source,
                        const Motion &motion, const std::string &landmarks, double max,
                        double round_trip_mean) {
  const Surface target = retriangulated(source, motion);
  const std::string source_file =
      dir.write("source.off", test::off_text(source.positions, source.triangles));
  const std::string target_file =
      dir.write("target.off", test::off_text(target.positions, target.triangles));
  std::vector<std::string> arguments{
      "match",  source_file,          target_file, "-o", dir.path("matched.ply"),
      "--both", dir.path("back.ply"), "--quiet"};
  if (!landmarks.empty())
    arguments.insert(arguments.end(), {"--landmarks", dir.write("pairs.txt", landmarks)});
  const test::RunResult run = test::run_cli(arguments);
  ASSERT_EQ(run.exit_code, 0) << name << ": " << run.err;
  // Source vertex i is target vertex i (the subdivision keeps the input's vertices first).
  const std::vector<Vec3> truth(target.positions.begin(),
                                target.positions.begin() + long(source.positions.size()));
  const MatchFigures forward = judged(dir.path("matched.ply"), source, target, truth, motion);
  EXPECT_LE(forward.mean, 0.005) << name;
  EXPECT_LE(forward.max, max) << name;
  EXPECT_EQ(forward.turned_over, 0) << name;
  const auto [trip_mean, trip_max] =
      round_trip(dir.path("matched.ply"), dir.path("back.ply"), source, target);
  EXPECT_LE(trip_mean, round_trip_mean) << name;
  std::cout << name << ": " << source.positions.size() << " -> " << target.positions.size()
            << " vertices, matched within " << 100 * forward.mean << "% (mean), "
            << 100 * forward.max << "% (max) of the diagonal, " << forward.turned_over
            << " turned over; round trip " << 100 * trip_mean << "% (mean), " << 100 * trip_max
            << "% (max)\n";
}

struct Case {
  std::string name;
  Surface source;
};

std::vector<Case> genus_zero_cases(const test::TempDir &dir) {
  std::vector<Case> cases;
  cases.push_back({"maxplanck", read_surface(test::data_path("maxplanck.nf25k.off"))});
  EXPECT_EQ(test::run_cli({"make", "genus", "-g", "0", "-o", dir.path("g0.off")}).exit_code, 0);
  cases.push_back({"generated genus 0", read_surface(dir.path("g0.off"))});
  EXPECT_EQ(test::run_cli(
                {"make", "blob", "--tentacles", "3", "--length", "1.5", "-o", dir.path("blob.off")})
                .exit_code,
            0);
  cases.push_back({"blob, 3 short limbs", read_surface(dir.path("blob.off"))});
  return cases;
}

TEST(Match, TheSameSurfaceRetriangulatedMovedAndRescaledIsFoundAutomatically) {
  const test::TempDir dir;
  unsigned seed = 11;
  for (const Case &c : genus_zero_cases(dir))
    expect_found_again(dir, c.name, c.source, random_motion(seed++, 2.7), "", 0.02, 0.01);
}

TEST(Match, ThreeLandmarksFixTheMapAndMoreAreFittedInLeastSquares) {
  const test::TempDir dir;
  const Surface source = read_surface(test::data_path("maxplanck.nf25k.off"));
  const Motion motion = random_motion(5, 0.3);
  const Surface target = retriangulated(source, motion);
  const std::string source_file =
      dir.write("source.off", test::off_text(source.positions, source.triangles));
  const std::string target_file =
      dir.write("target.off", test::off_text(target.positions, target.triangles));
  const std::vector<Vec3> truth(target.positions.begin(),
                                target.positions.begin() + long(source.positions.size()));
  // The landmarks land on their vertices: exactly with three (float output), closely with four.
  const std::pair<std::string, double> landmark_files[] = {
      {"100 100\n5000 5000\n9000 9000\n", 1e-5},
      {"# four pairs\n100 100\n5000 5000\n9000 9000\n12000 12000\n", 2e-3}};
  for (const auto &[pairs, tolerance] : landmark_files) {
    const std::string landmarks = dir.write("pairs.txt", pairs);
    const test::RunResult run =
        test::run_cli({"match", source_file, target_file, "-o", dir.path("matched.ply"),
                       "--landmarks", landmarks, "--quiet"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const MatchFigures figures = judged(dir.path("matched.ply"), source, target, truth, motion);
    EXPECT_LE(figures.mean, 0.005);
    EXPECT_LE(figures.max, 0.02);
    EXPECT_EQ(figures.turned_over, 0);
    const test::WrittenMesh written = test::read_written_mesh(dir.path("matched.ply"), false);
    for (int v : {100, 5000, 9000}) {
      const Vec3 p{written.columns.at("x")[size_t(v)], written.columns.at("y")[size_t(v)],
                   written.columns.at("z")[size_t(v)]};
      EXPECT_LT(norm(sub(p, truth[size_t(v)])) / diagonal(target.positions), tolerance)
          << "landmark " << v;
    }
  }
}

TEST(Match, WhatCannotBeMatchedIsRefusedWithTheReason) {
  const test::TempDir dir;
  const std::string sphere = dir.path("sphere.off"), torus = dir.path("torus.off");
  ASSERT_EQ(test::run_cli({"make", "sphere", "-o", sphere}).exit_code, 0);
  ASSERT_EQ(test::run_cli({"make", "torus", "-o", torus}).exit_code, 0);
  test::RunResult run = test::run_cli({"match", sphere, torus, "-o", dir.path("m.ply")});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("genus 1"), std::string::npos) << run.err;
  ASSERT_EQ(test::run_cli({"make", "genus", "-g", "3", "-o", dir.path("g3.off")}).exit_code, 0);
  run = test::run_cli({"match", dir.path("g3.off"), dir.path("g3.off"), "-o", dir.path("m.ply")});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("genus 0, 1 and 2 so far"), std::string::npos) << run.err;
  run = test::run_cli({"match", sphere, sphere, "-o", dir.path("m.ply"), "--landmarks",
                       dir.write("bad.txt", "1 2\n3\n")});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("bad.txt:2"), std::string::npos) << run.err;
  run = test::run_cli({"match", sphere, sphere, "-o", dir.path("m.ply"), "--landmarks",
                       dir.write("far.txt", "1 2\n3 4\n5 99999\n")});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("99999"), std::string::npos) << run.err;
  run = test::run_cli({"match", sphere, sphere, "-o", dir.path("m.ply"), "--landmarks",
                       dir.write("two.txt", "1 2\n3 4\n")});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("three landmark pairs"), std::string::npos) << run.err;
  // Never over an input; an output that cannot carry the per-vertex properties is refused.
  const std::string before = test::file_bytes(sphere);
  EXPECT_EQ(test::run_cli({"match", sphere, torus, "-o", sphere}).exit_code, 2);
  EXPECT_EQ(test::run_cli({"match", sphere, sphere, "-o", dir.path("m.obj")}).exit_code, 2);
  EXPECT_EQ(test::file_bytes(sphere), before);
}

TEST(Match, ARoundSphereReportsTheRotationsThatFitAsWell) {
  const test::TempDir dir;
  const std::string sphere = dir.path("sphere.off"), moved = dir.path("moved.off");
  ASSERT_EQ(test::run_cli({"make", "sphere", "-o", sphere}).exit_code, 0);
  ASSERT_EQ(test::run_cli({"make", "sphere", "--rigid-motion", "-o", moved}).exit_code, 0);
  const test::RunResult run = test::run_cli(
      {"match", sphere, moved, "-o", dir.path("m.ply"), "--report", dir.path("r.json")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("other alignments fit almost as well"), std::string::npos) << run.out;
}

// Genus 1: the flat tori's lattices matched and the translation found from the conformal factors
// (the kitten: no symmetry), or fixed by landmarks (a ring of tubes: turned along its core it
// looks the same, so the automatic alignment must say it is not sure).
TEST(Match, GenusOneTheSameSurfaceRetriangulatedIsFoundOnItsFlatTorus) {
  const test::TempDir dir;
  ASSERT_EQ(test::run_cli({"make", "genus", "-g", "1", "-o", dir.path("g1.off")}).exit_code, 0);
  struct GenusOneCase {
    std::string name;
    Surface source;
    std::string landmarks;
  };
  const GenusOneCase cases[] = {
      {"kitten", read_surface(test::data_path("kitten.nf20k.off")), ""},
      {"ring of tubes, two landmarks", read_surface(dir.path("g1.off")), "100 100\n2000 2000\n"}};
  unsigned seed = 21;
  for (const GenusOneCase &c : cases) {
    if (!c.landmarks.empty()) {
      // Without them the ring's turns along its core are reported as fitting as well.
      const Surface target = retriangulated(c.source, random_motion(seed, 0.4));
      const test::RunResult unsure = test::run_cli(
          {"match", dir.write("source.off", test::off_text(c.source.positions, c.source.triangles)),
           dir.write("target.off", test::off_text(target.positions, target.triangles)), "-o",
           dir.path("matched.ply")});
      ASSERT_EQ(unsure.exit_code, 0) << unsure.err;
      EXPECT_NE(unsure.out.find("genus 1"), std::string::npos) << unsure.out;
      EXPECT_NE(unsure.out.find("other alignments fit almost as well"), std::string::npos)
          << unsure.out;
    }
    expect_found_again(dir, c.name, c.source, random_motion(seed++, 0.4), c.landmarks, 0.02, 0.005);
  }
}

// Two triangulations of the kitten made apart (10,000 and 40,000 vertices, the second at ten times
// the size): each source vertex lands on the other where the same point of the kitten is.
TEST(Match, GenusOneTwoTriangulationsMadeApartMeetAtTheSamePoints) {
  const test::TempDir dir;
  const Surface source = read_surface(test::data_path("kitten.nf20k.off"));
  const Surface target = read_surface(test::data_path("kitten.nv40k.off"));
  const test::RunResult run = test::run_cli({"match", test::data_path("kitten.nf20k.off"),
                                             test::data_path("kitten.nv40k.off"), "-o",
                                             dir.path("matched.ply"), "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const test::WrittenMesh written = test::read_written_mesh(dir.path("matched.ply"), false);
  const double d = diagonal(target.positions);
  double mean = 0, worst = 0;
  for (size_t v = 0; v < source.positions.size(); ++v) {
    const Vec3 p{written.columns.at("x")[v], written.columns.at("y")[v],
                 written.columns.at("z")[v]};
    const Vec3 &s = source.positions[v];
    const double e = norm(sub(p, Vec3{10 * s[0], 10 * s[1], 10 * s[2]})) / d;
    mean += e / double(source.positions.size());
    worst = std::max(worst, e);
  }
  EXPECT_LE(mean, 0.002);
  EXPECT_LE(worst, 0.01);
  std::cout << "kitten.nf20k -> kitten.nv40k: " << 100 * mean << "% (mean), " << 100 * worst
            << "% (max) of the diagonal from the same point\n";
}

// A genus-1 source as users bring it, with a vertex on no face and two faces written twice (one
// the other way round): matched on its own vertices as the clean kitten is, the vertex on no face
// left unmatched (its target face -1).
TEST(Match, GenusOneDefectsAreSetAsideAndEveryVertexKeepsItsPlace) {
  const test::TempDir dir;
  const std::string target = test::data_path("kitten.nv40k.off");
  Surface kitten = read_surface(test::data_path("kitten.nf20k.off"));
  const size_t n = kitten.positions.size();
  ASSERT_EQ(test::run_cli({"match", test::data_path("kitten.nf20k.off"), target, "-o",
                           dir.path("clean.ply"), "--quiet"})
                .exit_code,
            0);
  kitten.positions.push_back({5, 5, 5});
  kitten.triangles.push_back(kitten.triangles[100]);
  kitten.triangles.push_back(
      {kitten.triangles[7][0], kitten.triangles[7][2], kitten.triangles[7][1]});
  const std::string source =
      dir.write("defects.off", test::off_text(kitten.positions, kitten.triangles));
  const test::RunResult run =
      test::run_cli({"match", source, target, "-o", dir.path("defects.ply"), "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto clean = test::read_written_mesh(dir.path("clean.ply"), false).columns;
  const auto defects = test::read_written_mesh(dir.path("defects.ply"), false).columns;
  ASSERT_EQ(defects.at("x").size(), n + 1);
  double worst = 0;
  for (size_t v = 0; v < n; ++v)
    for (const char *axis : {"x", "y", "z"})
      worst = std::max(worst, std::abs(defects.at(axis)[v] - clean.at(axis)[v]));
  EXPECT_LT(worst, 1e-3 * diagonal(read_surface(target).positions));
  EXPECT_EQ(defects.at("target_face")[n], -1) << "the vertex on no face has no match";
}

// Genus 2: both canonical (hyperelliptic) maps, their six branch values matched by a Moebius
// transformation, the sheets followed across the surface. A generated genus-2 surface is found
// automatically; the "eight" is symmetric (several automorphisms fit as well), so three landmarks
// pick the right one.
TEST(Match, GenusTwoTheSameSurfaceRetriangulatedIsFoundThroughItsCanonicalMap) {
  const test::TempDir dir;
  ASSERT_EQ(test::run_cli({"make", "genus", "-g", "2", "-o", dir.path("g2.off")}).exit_code, 0);
  struct GenusTwoCase {
    std::string name;
    Surface source;
    std::string landmarks;
    double max;
  };
  const GenusTwoCase cases[] = {{"generated genus 2", read_surface(dir.path("g2.off")), "", 0.02},
                                {"eight, three landmarks",
                                 read_surface(test::data_path("eight.off")),
                                 "10 10\n200 200\n400 400\n", 0.03}};
  unsigned seed = 31;
  for (const GenusTwoCase &c : cases)
    expect_found_again(dir, c.name, c.source, random_motion(seed++, 1.7), c.landmarks, c.max, 0.01);
}

// Two tori of revolution of different shape: the extremal map between them stretches by the
// ratio of their exact moduli, i sqrt(R^2 - r^2) / r.
TEST(Match, GenusOneBetweenDifferentToriTheDilatationIsTheRatioOfTheirModuli) {
  const test::TempDir dir;
  const std::string thin = dir.path("thin.off"), fat = dir.path("fat.off");
  ASSERT_EQ(test::run_cli({"make", "torus", "-R", "3", "-r", "1", "-o", thin}).exit_code, 0);
  ASSERT_EQ(
      test::run_cli({"make", "torus", "-R", "2", "-r", "1", "--rigid-motion", "-o", fat}).exit_code,
      0);
  const test::RunResult run =
      test::run_cli({"match", thin, fat, "-o", dir.path("m.ply"), "--report", dir.path("r.json"),
                     "--landmarks", dir.write("pairs.txt", "0 0\n")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string report = test::file_bytes(dir.path("r.json"));
  const auto number_after = [&](const std::string &key) {
    const size_t at = report.find("\"" + key + "\"");
    EXPECT_NE(at, std::string::npos) << key;
    return std::stod(report.substr(report.find(':', at) + 1));
  };
  const double exact = std::sqrt(8.0) / std::sqrt(3.0);
  EXPECT_NEAR(number_after("dilatation"), exact, 0.01 * exact);
  std::cout << "dilatation " << number_after("dilatation") << ", exact " << exact << "\n";
}

// `meromorph transfer`: a head's colours, quality, texture coordinates and a label per vertex
// (functions of the position; the label splits the head at its median height) carried onto the
// same head subdivided, turned, shrunk and moved. The subdivision's first vertices are the head's,
// so their true values are known; labels are taken whole, never mixed.
TEST(Transfer, AHeadsValuesOntoItsMovedSubdivision) {
  const test::TempDir dir;
  const Surface head = read_surface(test::data_path("maxplanck.nf25k.off"));
  const size_t n = head.positions.size();
  Vec3 low = head.positions.front(), high = low;
  for (const Vec3 &p : head.positions)
    for (size_t k = 0; k < 3; ++k)
      low[k] = std::min(low[k], p[k]), high[k] = std::max(high[k], p[k]);
  const auto unit = [&](const Vec3 &p, size_t k) { return (p[k] - low[k]) / (high[k] - low[k]); };
  std::ostringstream ply;
  ply << "ply\nformat ascii 1.0\nelement vertex " << n
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty "
         "uchar green\nproperty uchar blue\nproperty float quality\nproperty float texture_u\n"
         "property float texture_v\nproperty int part\nelement face "
      << head.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  ply.precision(9);
  for (const Vec3 &p : head.positions)
    ply << p[0] << " " << p[1] << " " << p[2] << " " << std::lround(255 * unit(p, 0)) << " "
        << std::lround(255 * unit(p, 1)) << " " << std::lround(255 * unit(p, 2)) << " "
        << unit(p, 2) << " " << unit(p, 0) << " " << unit(p, 1) << " " << (unit(p, 2) > 0.5)
        << "\n";
  for (const auto &t : head.triangles)
    ply << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  const std::string painted = dir.write("painted.ply", ply.str());
  ASSERT_EQ(test::run_cli({"make", "subdivide", test::data_path("maxplanck.nf25k.off"), "-o",
                           dir.path("scan.off"), "--rigid-motion", "--seed", "3", "--scale", "0.5"})
                .exit_code,
            0);
  const test::RunResult run =
      test::run_cli({"transfer", dir.path("scan.off"), painted, "-o", dir.path("scan.ply"),
                     "--report", dir.path("report.json")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("carried red, green, blue, quality, texture_u, texture_v, part"),
            std::string::npos)
      << run.out;
  const test::WrittenMesh written = test::read_written_mesh(dir.path("scan.ply"));
  const auto &c = written.columns;
  ASSERT_EQ(c.at("x").size(), n + head.triangles.size() * 3 / 2);
  double colour = 0, quality = 0, uv = 0;
  int labels_right = 0;
  for (size_t v = 0; v < n; ++v) {
    const Vec3 &p = head.positions[v];
    colour += (std::abs(c.at("red")[v] - 255 * unit(p, 0)) +
               std::abs(c.at("green")[v] - 255 * unit(p, 1)) +
               std::abs(c.at("blue")[v] - 255 * unit(p, 2))) /
              (3.0 * double(n));
    quality += std::abs(c.at("quality")[v] - unit(p, 2)) / double(n);
    uv += std::hypot(c.at("texture_u")[v] - unit(p, 0), c.at("texture_v")[v] - unit(p, 1)) /
          double(n);
    labels_right += c.at("part")[v] == double(unit(p, 2) > 0.5);
  }
  for (double label : c.at("part"))
    ASSERT_TRUE(label == 0 || label == 1) << "a label is taken whole: " << label;
  EXPECT_LT(colour, 1.5);
  EXPECT_LT(quality, 0.005);
  EXPECT_LT(uv, 0.005);
  EXPECT_GE(labels_right, int(0.99 * double(n)));
  std::cout << "colour error " << colour << " of 255, quality " << quality << ", texture " << uv
            << ", labels right " << labels_right << " of " << n << "\n";
  // Nothing to carry, an output that cannot carry values, and the input never written over.
  test::RunResult refused =
      test::run_cli({"transfer", painted, dir.path("scan.off"), "-o", dir.path("x.ply")});
  EXPECT_EQ(refused.exit_code, 3);
  EXPECT_NE(refused.err.find("no per-vertex values"), std::string::npos) << refused.err;
  EXPECT_EQ(
      test::run_cli({"transfer", dir.path("scan.off"), painted, "-o", dir.path("x.obj")}).exit_code,
      2);
  const std::string before = test::file_bytes(painted);
  EXPECT_EQ(test::run_cli({"transfer", dir.path("scan.off"), painted, "-o", painted}).exit_code, 2);
  EXPECT_EQ(test::file_bytes(painted), before);
}

// `remesh --like TEMPLATE`: a collection remeshed like one template. Each output has the
// template's triangles, its vertex i on the input where the template's vertex i is: the head's
// subdivisions moved two ways (their first vertices are the head's, moved), and the kitten
// remeshed apart at ten times the size (genus 1).
TEST(Remesh, LikeATemplateGivesACollectionOneConnectivity) {
  const test::TempDir dir;
  const std::string head = test::data_path("maxplanck.nf25k.off");
  const Surface like = read_surface(head);
  for (const char *seed : {"3", "4"}) {
    const std::string scan = dir.path(std::string("scan") + seed + ".off");
    ASSERT_EQ(test::run_cli({"make", "subdivide", head, "-o", scan, "--rigid-motion", "--seed",
                             seed, "--scale", "0.5"})
                  .exit_code,
              0);
    const test::RunResult run =
        test::run_cli({"remesh", scan, "-o", dir.path("like.off"), "--like", head, "--quiet"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Surface input = read_surface(scan), out = read_surface(dir.path("like.off"));
    EXPECT_EQ(out.triangles, like.triangles) << "the template's triangles";
    ASSERT_EQ(out.positions.size(), like.positions.size());
    const double d = diagonal(input.positions);
    double mean = 0, worst = 0;
    for (size_t v = 0; v < out.positions.size(); ++v) {
      const double e = norm(sub(out.positions[v], input.positions[v])) / d;
      mean += e / double(out.positions.size());
      worst = std::max(worst, e);
    }
    EXPECT_LE(mean, 0.005);
    EXPECT_LE(worst, 0.02);
    std::cout << "head like the head, seed " << seed << ": vertex i within " << 100 * mean
              << "% (mean), " << 100 * worst << "% (max) of the diagonal\n";
  }
  const Surface kitten = read_surface(test::data_path("kitten.nf20k.off"));
  ASSERT_EQ(
      test::run_cli({"remesh", test::data_path("kitten.nv40k.off"), "-o", dir.path("kitten.off"),
                     "--like", test::data_path("kitten.nf20k.off"), "--quiet"})
          .exit_code,
      0);
  const Surface out = read_surface(dir.path("kitten.off"));
  EXPECT_EQ(out.triangles, kitten.triangles);
  double mean = 0;
  for (size_t v = 0; v < out.positions.size(); ++v) {
    const Vec3 &p = kitten.positions[v];
    mean += norm(sub(out.positions[v], Vec3{10 * p[0], 10 * p[1], 10 * p[2]})) /
            diagonal(out.positions) / double(out.positions.size());
  }
  EXPECT_LE(mean, 0.002);
  // The template sets the size: no size option with it; landmarks only with it.
  EXPECT_EQ(
      test::run_cli({"remesh", head, "-o", dir.path("x.off"), "--like", head, "--vertices", "100"})
          .exit_code,
      2);
  EXPECT_EQ(test::run_cli({"remesh", head, "-o", dir.path("x.off"), "--landmarks",
                           dir.write("pairs.txt", "1 1\n")})
                .exit_code,
            2);
}

} // namespace
} // namespace meromorph
