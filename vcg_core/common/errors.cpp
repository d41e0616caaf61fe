#include "common/errors.h"

#include <algorithm>

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

const char *remedy_code(Remedy remedy) {
  switch (remedy) {
  case Remedy::repair:
    return "repair";
  case Remedy::close_holes:
    return "close_holes";
  case Remedy::split_nonmanifold:
    return "split_nonmanifold";
  case Remedy::remove_zero_area_faces:
    return "remove_zero_area_faces";
  case Remedy::remove_duplicate_faces:
    return "remove_duplicate_faces";
  case Remedy::remesh:
    return "remesh";
  case Remedy::refine:
    return "refine";
  case Remedy::generic_form_pair:
    return "generic_form_pair";
  case Remedy::shorten_thin_parts:
    return "shorten_thin_parts";
  case Remedy::check_units:
    return "check_units";
  case Remedy::choose_uv_kind:
    return "choose_uv_kind";
  }
  return "unknown";
}

void add_remedy(std::vector<Remedy> &remedies, Remedy remedy) {
  if (std::find(remedies.begin(), remedies.end(), remedy) == remedies.end())
    remedies.push_back(remedy);
}

std::string join_phrases(const std::vector<std::string> &phrases) {
  std::string text;
  for (const std::string &phrase : phrases)
    text += (text.empty() ? "" : "; ") + phrase;
  return text;
}

} // namespace meromorph
