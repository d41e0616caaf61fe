#include "landmarks_file.h"

#include <cstdint>
#include <fstream>
#include <sstream>

#include "common/errors.h"

namespace meromorph::cli {

std::vector<std::pair<int, int>> read_landmarks(const std::string &path) {
  std::ifstream file(path);
  if (!file) throw ArgumentError(path + ": cannot read the landmarks file");
  std::vector<std::pair<int, int>> pairs;
  std::string line;
  for (int number = 1; std::getline(file, line); ++number) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    long long i = 0, j = 0;
    std::string extra;
    if (!(words >> i)) continue; // blank or comment
    if (!(words >> j) || (words >> extra) || i < 0 || j < 0 || i > INT32_MAX || j > INT32_MAX)
      throw InputError(path + ":" + std::to_string(number) +
                       ": a landmark line is two vertex indices, source then target (\"12 40\")");
    pairs.emplace_back(int(i), int(j));
  }
  return pairs;
}

} // namespace meromorph::cli
