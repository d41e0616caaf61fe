#include "common/errors.h"

namespace meromorph {

std::string list_indices(const std::vector<int> &indices, size_t shown) {
  std::string text;
  const size_t n = std::min(shown, indices.size());
  for (size_t i = 0; i < n; ++i) {
    if (i) text += ", ";
    text += std::to_string(indices[i]);
  }
  if (indices.size() > n) text += " and " + std::to_string(indices.size() - n) + " more";
  return text;
}

std::string join_phrases(const std::vector<std::string> &phrases) {
  std::string text;
  for (const std::string &phrase : phrases)
    text += (text.empty() ? "" : "; ") + phrase;
  return text;
}

} // namespace meromorph
