#include "common/remedy.h"

namespace meromorph {

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
  case Remedy::add_vertices:
    return "add_vertices";
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

} // namespace meromorph
