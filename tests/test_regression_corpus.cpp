// Every input that ever crashed meromorph (tests/fuzz_corpus/regressions/) through the real CLI:
// `info` and `param` exit with the code listed here (0 mapped, 3 refused with a message that
// names the file), never 1 (internal failure) or a signal, and `info --json` prints JSON. A new
// regression file needs its line.
#include <filesystem>
#include <map>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support.h"

namespace meromorph {
namespace {

const std::map<std::string, int> expected_exit_code = {
    {"bare_exponent.ply", 3},
    {"binary_face_of_1000_corners.ply", 3}, // one flat polygon: an open surface
    {"count_wraps_32_bits.ply", 3},
    {"crlf_bom.obj", 0},
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
    {"one_coordinate_1e308.off", 3},
    {"per_face_list_of_255_floats.ply", 0},
    {"pillow.off", 3},
    {"plus_minus_number.ply", 3},
    {"quad_index_out_of_range.ply", 3},
    {"torus_1e160.off", 0},
    {"truncated_data.ply", 3},
    {"two_corner_face.ply", 3},
    {"vertex_declared_twice.ply", 3},
    {"zero_corner_face.ply", 3},
};

// Files that `info` accepts but that have no valid map: a vertex pulled 1e8 away makes a spike
// that shrinks below double precision. (The 12 x 6 grid torus at 1e160 maps: its double pole on
// the fourth origin tried.)
const std::map<std::string, int> param_exit_code = {{"eight_with_a_spike_1e8_long.off", 3},
                                                    {"eight_with_a_spike_4e9_long.off", 3}};

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
    ++checked;
  }
  EXPECT_EQ(checked, expected_exit_code.size()) << "every listed file is in the corpus";
}

} // namespace
} // namespace meromorph
