// Progress reporting and cancellation.
#include <gtest/gtest.h>

#include "common/errors.h"
#include "common/progress.h"

namespace meromorph {
namespace {

TEST(Progress, RangesMapIntoTheParentAndCancelThrows) {
  std::vector<double> seen;
  bool keep_going = true;
  Progress progress([&](double fraction, const std::string &) {
    seen.push_back(fraction);
    return keep_going;
  });
  progress.report(0.5, "half");
  const Progress second_half = progress.range(0.5, 1.0);
  second_half.report(0.5, "three quarters");
  second_half.range(0.0, 0.5).report(1.0, "still three quarters");
  second_half.report(2.0, "clamped");
  EXPECT_EQ(seen, (std::vector<double>{0.5, 0.75, 0.75, 1.0}));
  keep_going = false;
  EXPECT_THROW(progress.report(0.9, "stop"), Cancelled);
  EXPECT_NO_THROW(Progress().report(0.3, "nobody listens"));
}

} // namespace
} // namespace meromorph
