// Every input that ever crashed, hung or failed meromorph (tests/fuzz_corpus/regressions/, their
// origins in tests/fuzz_corpus/README.md) through the real CLI, in every subcommand and with every
// option that changes the path: `info` and `param` exit with the code listed here (0 mapped, 3
// refused with a message that names the file), `info --json` prints JSON, and `param
// --close-holes --split-nonmanifold`, `remesh` (plain and with both options) and `forms` exit 0 or
// 3 (or the code listed for them): never 1 (internal failure) or a signal. A new regression file
// needs its line.
#include <filesystem>
#include <map>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support.h"

namespace meromorph {
namespace {

const std::map<std::string, int> expected_exit_code = {
    {"bare_exponent.ply", 3},
    {"binary_face_of_1000_corners.ply", 3}, // a flat polygon's fan: zero-area faces that stay
    {"count_wraps_32_bits.ply", 3},
    {"crlf_bom.obj", 0},
    {"eight_1e-50.off", 0},
    {"element_without_properties_2147483647.ply", 0},
    {"face_1e200.off", 0}, // open: its hole closed for the computation
    {"face_1e-300.off", 0},
    {"eight_with_a_spike_1e8_long.off", 0}, // CHOLMOD was handed an empty system (segfault)
    {"eight_with_a_spike_4e9_long.off", 0}, // the Laplacian's factorization failed: exit 1
    {"face_of_1000_corners.ply", 3},
    {"hex_float.ply", 3},
    {"missing_count.ply", 3},
    {"negative_list_count.ply", 3},
    {"not_utf8_token.off", 3}, // info --json: exit 1, the message was not UTF-8
    {"no_final_newline.off", 0},
    {"octahedron_1e-200.off", 0},
    {"octahedron_1e200.off", 0},
    {"octahedron_1e40.off", 0},
    {"one_coordinate_1e308.off", 3},
    {"per_face_list_of_255_floats.ply", 0},
    {"pillow.off", 0}, // two faces on three vertices: one left out
    {"plus_minus_number.ply", 3},
    {"quad_index_out_of_range.ply", 3},
    {"torus_1e160.off", 0},
    {"torus_1e160_remeshed_to_a_speck.off", 0},
    {"torus_8_rings_with_a_needle.off", 0},
    {"truncated_data.ply", 3},
    {"two_corner_face.ply", 3},
    {"vertex_declared_twice.ply", 3},
    {"zero_corner_face.ply", 3},
};

// Files that `info` accepts but that have no valid map: a vertex pulled 1e8 away makes a spike
// that shrinks below double precision. (The 12 x 6 grid torus at 1e160 maps: its double pole on
// the fourth origin tried.)
const std::map<std::string, int> param_exit_code = {{"eight_with_a_spike_1e8_long.off", 3},
                                                    {"eight_with_a_spike_4e9_long.off", 3},
                                                    {"torus_8_rings_with_a_needle.off", 3}};

// Exit codes of the other jobs where they are known exactly (else 0 or 3): the reproducers of
// remesh's and --close-holes' failures.
const std::map<std::pair<std::string, std::string>, int> job_exit_code = {
    {{"face_1e200.off", "param --close-holes --split-nonmanifold"}, 0},
    {{"face_1e-300.off", "param --close-holes --split-nonmanifold"}, 0},
    {{"face_1e200.off", "remesh --close-holes --split-nonmanifold"}, 0},
    {{"face_1e-300.off", "remesh --close-holes --split-nonmanifold"}, 0},
    {{"octahedron_1e40.off", "remesh"}, 0},
    {{"octahedron_1e200.off", "remesh"}, 0},
    {{"octahedron_1e-200.off", "remesh"}, 0},
    {{"torus_1e160.off", "remesh"}, 0},
    {{"eight_1e-50.off", "remesh"}, 0},
    {{"eight_1e-50.off", "forms"}, 0},
};

// Remeshed to 12 vertices (the fuzz target's target) it crowds into a spot: refused, where vcglib's
// Hausdorff grid over the speck counted cells past an int and looped.
TEST(RegressionCorpus, ARemeshCrowdedIntoASpotIsRefusedNotLooped) {
  const std::filesystem::path file = std::filesystem::path(MEROMORPH_TEST_DATA).parent_path() /
                                     "fuzz_corpus" / "regressions" /
                                     "torus_1e160_remeshed_to_a_speck.off";
  test::TempDir dir;
  const test::RunResult r = test::run_cli(
      {"remesh", file.string(), "-o", dir.path("out.ply"), "--vertices", "12", "--quiet"});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("Euler characteristic"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path("out.ply")));
}

// The jobs besides `info` and `param`, as the words after the subcommand's input.
const std::vector<std::pair<std::string, std::vector<std::string>>> other_jobs = {
    {"param --close-holes --split-nonmanifold", {"param", "--close-holes", "--split-nonmanifold"}},
    {"remesh", {"remesh", "--vertices", "300"}},
    {"remesh --close-holes --split-nonmanifold",
     {"remesh", "--vertices", "300", "--close-holes", "--split-nonmanifold"}},
    {"forms", {"forms"}},
};

TEST(RegressionCorpus, EveryInputThatEverCrashedGetsItsExitCode) {
  const std::filesystem::path folder =
      std::filesystem::path(MEROMORPH_TEST_DATA).parent_path() / "fuzz_corpus" / "regressions";
  test::TempDir dir;
  size_t checked = 0;
  for (const auto &entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    const auto expected = expected_exit_code.find(name);
    ASSERT_NE(expected, expected_exit_code.end()) << name << " has no expected exit code here";
    const test::RunResult info = test::run_cli({"info", entry.path().string()});
    const test::RunResult param =
        test::run_cli({"param", entry.path().string(), "-o", dir.path("out.ply"), "--sphere",
                       dir.path("sphere.ply"), "--report", dir.path("report.json"), "--quiet"});
    const int param_expected =
        param_exit_code.count(name) ? param_exit_code.at(name) : expected->second;
    EXPECT_EQ(param.exit_code, param_expected) << name << ": " << param.err;
    EXPECT_EQ(info.exit_code, expected->second) << name << ": " << info.err;
    if (param_expected == 3) {
      EXPECT_NE(param.err.find(name), std::string::npos)
          << name << ": the message names the file: " << param.err;
    }
    // `info --json` prints JSON whatever the file holds.
    const test::RunResult json = test::run_cli({"info", "--json", entry.path().string()});
    EXPECT_EQ(json.exit_code, expected->second) << name << ": " << json.err;
    EXPECT_TRUE(nlohmann::json::accept(json.out)) << name << ": " << json.out;
    for (const auto &[job, words] : other_jobs) {
      std::vector<std::string> arguments = {words[0], entry.path().string(), "--quiet"};
      arguments.insert(arguments.end(), words.begin() + 1, words.end());
      if (words[0] != "forms") arguments.insert(arguments.end(), {"-o", dir.path("job.ply")});
      const test::RunResult r = test::run_cli(arguments);
      const auto known = job_exit_code.find({name, job});
      if (known != job_exit_code.end())
        EXPECT_EQ(r.exit_code, known->second) << name << ", " << job << ": " << r.err;
      else
        EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 3)
            << name << ", " << job << ": exit " << r.exit_code << ": " << r.err;
    }
    ++checked;
  }
  EXPECT_EQ(checked, expected_exit_code.size()) << "every listed file is in the corpus";
}

} // namespace
} // namespace meromorph
