// A progress bar on stderr for runs that take more than a second.
//
// In:  whether to stay quiet.
// Out: a Progress whose reports draw "[#####     ]  50% stage" on stderr (only when stderr is a
//      terminal or after the first second), called by the job itself (Progress::on_any_thread);
//      none when quiet. `finish` clears the line.
#pragma once

#include <chrono>
#include <iostream>
#include <string>

#include <unistd.h>

#include "common/progress.h"

namespace meromorph::cli {

class TerminalProgress {
public:
  explicit TerminalProgress(bool quiet) : quiet_(quiet) {}

  Progress progress() {
    if (quiet_) return Progress();
    // Drawn when the job reports, from its own thread: the job needs no thread of its own.
    return Progress::on_any_thread([this](double fraction, const std::string &stage) {
      draw(fraction, stage);
      return true;
    });
  }

  void finish() {
    if (drawn_) std::cerr << "\r" << std::string(72, ' ') << "\r" << std::flush;
  }

private:
  void draw(double fraction, const std::string &stage) {
    if (quiet_) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed < 1.0) return;
    const int width = 30, filled = int(fraction * width + 0.5);
    std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] "
              << int(fraction * 100 + 0.5) << "% " << stage.substr(0, 32) << std::string(8, ' ')
              << (isatty(2) ? "" : "\n") << std::flush;
    drawn_ = true;
  }

  bool quiet_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

} // namespace meromorph::cli
