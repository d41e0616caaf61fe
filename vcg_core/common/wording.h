// Messages in the user's words.
//
// In:  a count and the singular and plural of what is counted.
// Out: "1 hole", "3 holes".
#pragma once

#include <string>

namespace meromorph {

inline std::string plural(size_t n, const char *one, const char *many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

} // namespace meromorph
