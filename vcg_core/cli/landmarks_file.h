// The landmarks file of `match` and `transfer`: lines "i j" (a SOURCE vertex and a TARGET vertex);
// "#" starts a comment, blank lines are skipped.
//
// In:  a path. Out: the pairs in file order.
// Errors: ArgumentError when the file cannot be read; InputError naming the line that is not two
//      non-negative vertex indices.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace meromorph::cli {

std::vector<std::pair<int, int>> read_landmarks(const std::string &path);

} // namespace meromorph::cli
