// The command-line tool's own peak memory, for its reports.
//
// In:  nothing. Out: the most resident memory this process has had so far, in MB (VmHWM of
//      /proc/self/status: counted from the tool's start, not its parent's), or -1 where the
//      system does not say.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

namespace meromorph::cli {

inline double own_peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) {
      std::istringstream words(line.substr(6));
      double kilobytes = -1;
      words >> kilobytes;
      return kilobytes >= 0 ? kilobytes / 1024.0 : -1;
    }
  return -1;
}

} // namespace meromorph::cli
