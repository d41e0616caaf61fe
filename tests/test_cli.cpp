// The command-line tool as a user runs it: version, help, exit codes, JSON, make.
#include <cmath>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support.h"

namespace meromorph {
namespace {

using test::run_cli;

TEST(Cli, VersionAndHelp) {
  const test::RunResult version = run_cli({"--version"});
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.out.find(std::string("meromorph ") + MEROMORPH_VERSION), std::string::npos);
  for (std::vector<std::string> help : {std::vector<std::string>{"--help"},
                                        {"info", "--help"},
                                        {"make", "--help"},
                                        {"make", "genus", "--help"}}) {
    const test::RunResult r = run_cli(help);
    EXPECT_EQ(r.exit_code, 0) << help[0];
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << r.out;
  }
}

TEST(Cli, BadArgumentsExitWithTwo) {
  EXPECT_EQ(run_cli({}).exit_code, 2);
  EXPECT_EQ(run_cli({"frobnicate"}).exit_code, 2);
  EXPECT_EQ(run_cli({"info"}).exit_code, 2);
  const test::RunResult missing = run_cli({"info", "/nonexistent/mesh.off"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("no such file"), std::string::npos) << missing.err;
  EXPECT_EQ(run_cli({"info", test::data_path("README.md")}).exit_code, 2);
  EXPECT_EQ(run_cli({"make", "torus", "-R", "1", "-r", "2", "-o", "/tmp/x.ply"}).exit_code, 2);
}

TEST(Cli, InfoReportsGenusAsTextAndJson) {
  const test::RunResult text = run_cli({"info", test::data_path("eight.off")});
  EXPECT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("genus           2"), std::string::npos) << text.out;

  const test::RunResult json = run_cli({"info", "--json", test::data_path("knot.obj")});
  EXPECT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json report = nlohmann::json::parse(json.out);
  EXPECT_EQ(report["topology"]["genus"], 1);
  EXPECT_EQ(report["topology"]["vertices"], 1440);
  EXPECT_EQ(report["topology"]["edges"], 4320);
  EXPECT_EQ(report["topology"]["faces"], 2880);
  EXPECT_EQ(report["topology"]["components"], 1);
  EXPECT_TRUE(report["ok"].get<bool>());
  EXPECT_TRUE(report["findings"].empty());
}

TEST(Cli, JsonFindingsOfAnOpenMesh) {
  // By default param closes the holes (and welds the seam's duplicate vertices) for the
  // computation; with --strict it refuses them.
  for (const bool strict : {false, true}) {
    std::vector<std::string> arguments = {"info", "--json", test::data_path("eight.open.off")};
    if (strict) arguments.push_back("--strict");
    const test::RunResult r = run_cli(arguments);
    EXPECT_EQ(r.exit_code, strict ? 3 : 0) << r.err;
    const nlohmann::json report = nlohmann::json::parse(r.out);
    EXPECT_FALSE(report["ok"].get<bool>());
    EXPECT_EQ(report["param_maps_it_as_it_is"].get<bool>(), !strict);
    bool found_loops = false;
    for (const auto &finding : report["findings"])
      if (finding["code"] == "boundary_loops") {
        found_loops = true;
        EXPECT_EQ(finding["sizes"], nlohmann::json::array({24, 24, 24, 24}));
        EXPECT_EQ(finding["param"], strict ? "refused" : "closes the holes");
      }
    EXPECT_TRUE(found_loops) << r.out;
  }
}

TEST(Cli, MakeWritesSurfacesThatInfoAccepts) {
  test::TempDir dir;
  const std::vector<std::vector<std::string>> makes = {
      {"make", "sphere", "-s", "2", "-o", dir.path("sphere.ply")},
      {"make", "torus", "-R", "3", "-r", "1", "--resolution", "12", "-o", dir.path("torus.off")},
      {"make", "torus", "--method", "implicit", "--resolution", "16", "-o", dir.path("ti.obj")},
      {"make", "genus", "-g", "4", "--resolution", "16", "--rigid-motion", "--seed", "5", "-o",
       dir.path("g4.ply")},
  };
  const int genus[] = {0, 1, 1, 4};
  for (size_t i = 0; i < makes.size(); ++i) {
    const test::RunResult made = run_cli(makes[i]);
    ASSERT_EQ(made.exit_code, 0) << made.err;
    const test::RunResult info = run_cli({"info", "--json", makes[i].back()});
    ASSERT_EQ(info.exit_code, 0) << info.err;
    EXPECT_EQ(nlohmann::json::parse(info.out)["topology"]["genus"], genus[i]) << makes[i].back();
  }
}

TEST(Cli, FormsWritesAReportWithTheModulus) {
  test::TempDir dir;
  ASSERT_EQ(run_cli({"make", "torus", "-R", "2", "-r", "1", "--resolution", "40", "-o",
                     dir.path("torus.ply")})
                .exit_code,
            0);
  const test::RunResult r =
      run_cli({"forms", dir.path("torus.ply"), "--report", dir.path("report.json"), "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream stream(dir.path("report.json"));
  const nlohmann::json report = nlohmann::json::parse(stream);
  EXPECT_EQ(report["genus"], 1);
  EXPECT_NEAR(report["modulus"][1].get<double>(), std::sqrt(3.0), 0.01);
  EXPECT_NEAR(report["modulus"][0].get<double>(), 0.0, 0.01);
  for (const char *stage : {"read", "laplacian", "factorization", "harmonic", "holomorphic"})
    EXPECT_TRUE(report["timings_ms"].contains(stage)) << stage;
  EXPECT_LT(report["residuals"]["closedness"].get<double>(), 1e-12);
  EXPECT_LT(report["non_holomorphicity"]["mean"].get<double>(), 0.1);

  // Without --report, standard output is the JSON and nothing else (`forms IN > f.json`); the
  // summary line goes to standard error unless --quiet.
  for (const bool quiet : {true, false}) {
    const test::RunResult genus2 = quiet
                                       ? run_cli({"forms", test::data_path("eight.off"), "--quiet"})
                                       : run_cli({"forms", test::data_path("eight.off")});
    ASSERT_EQ(genus2.exit_code, 0) << genus2.err;
    ASSERT_TRUE(nlohmann::json::accept(genus2.out)) << genus2.out;
    EXPECT_EQ(nlohmann::json::parse(genus2.out)["riemann_matrix"].size(), 2u);
    EXPECT_EQ(genus2.err.find("genus 2, Riemann matrix") == std::string::npos, quiet) << genus2.err;
  }

  const test::RunResult open = run_cli({"forms", test::data_path("eight.hole.off")});
  EXPECT_EQ(open.exit_code, 3);
  EXPECT_NE(open.err.find("boundary loop"), std::string::npos) << open.err;
  EXPECT_EQ(run_cli({"forms", dir.path("torus.ply"), "--report", dir.path("torus.ply")}).exit_code,
            2);
}

} // namespace
} // namespace meromorph
