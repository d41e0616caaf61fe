// `info` says what `param` with the same options will do: on every test mesh and every input of
// the regression corpus, with the defaults and with --strict, a mesh info refuses is refused by
// param, and a mesh info accepts is mapped, unless the map itself shows the trouble (a part
// that shrinks below double precision, a Laplacian that cannot be factored, no valid map on this
// triangulation): what no look at the mesh can tell before computing.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.h"

namespace meromorph {
namespace {

bool refused_by_the_computed_map(const std::string &message) {
  return message.find("no valid map on this triangulation") != std::string::npos ||
         message.find("below double precision") != std::string::npos ||
         message.find("shrink") != std::string::npos ||
         message.find("could not be factored") != std::string::npos;
}

TEST(InfoAndParam, AgreeOnEveryTestMesh) {
  const std::filesystem::path data(MEROMORPH_TEST_DATA);
  std::vector<std::filesystem::path> inputs;
  for (const auto &folder : {data, data.parent_path() / "fuzz_corpus" / "regressions"})
    for (const auto &entry : std::filesystem::directory_iterator(folder)) {
      const std::string extension = entry.path().extension().string();
      if (extension == ".off" || extension == ".ply" || extension == ".obj" || extension == ".stl")
        inputs.push_back(entry.path());
    }
  ASSERT_GT(inputs.size(), 30u);
  test::TempDir dir;
  int refused = 0, mapped = 0;
  for (const auto &input : inputs)
    for (const bool strict : {false, true}) {
      std::vector<std::string> info_call = {"info", input.string()},
                               param_call = {"param", input.string(), "-o", dir.path("out.ply"),
                                             "--quiet"};
      if (strict) {
        info_call.push_back("--strict");
        param_call.push_back("--strict");
      }
      const test::RunResult info = test::run_cli(info_call), param = test::run_cli(param_call);
      const std::string name = input.filename().string() + (strict ? " --strict" : "");
      ASSERT_TRUE(info.exit_code == 0 || info.exit_code == 3) << name << ": " << info.err;
      if (info.exit_code == 3) {
        EXPECT_EQ(param.exit_code, 3)
            << name << ": info refuses it (" << info.err << ") but param says: " << param.err;
        ++refused;
      } else {
        EXPECT_TRUE(param.exit_code == 0 || refused_by_the_computed_map(param.err))
            << name << ": info accepts it but param says (exit " << param.exit_code
            << "): " << param.err;
        ++mapped;
      }
    }
  EXPECT_GT(refused, 10);
  EXPECT_GT(mapped, 10);
}

} // namespace
} // namespace meromorph
