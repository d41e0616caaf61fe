// Time per stage of a job.
//
// In:  the list the timings go to; each call to done(stage) when a stage ends.
// Out: (stage, milliseconds since the previous call or since the clock was made) appended to the
//      list. restart() starts the next stage's time now (after work timed elsewhere).
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace meromorph {

class StageClock {
public:
  explicit StageClock(std::vector<std::pair<std::string, double>> &timings) : timings_(timings) {}
  void done(const std::string &stage) {
    const auto now = std::chrono::steady_clock::now();
    timings_.push_back({stage, std::chrono::duration<double, std::milli>(now - start_).count()});
    start_ = now;
  }
  void restart() { start_ = std::chrono::steady_clock::now(); }

private:
  std::vector<std::pair<std::string, double>> &timings_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

} // namespace meromorph
