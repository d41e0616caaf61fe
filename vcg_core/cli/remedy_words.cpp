#include "cli/remedy_words.h"

namespace meromorph::cli {

std::string remedy_words(Remedy remedy) {
  switch (remedy) {
  case Remedy::repair:
    return "the safe repairs fix it: run again with --repair";
  case Remedy::close_holes:
    return "let meromorph close them for the computation only (--close-holes), or close them in "
           "the model (MeshLab: Filters > Remeshing, Simplification and Reconstruction > Close "
           "Holes; Blender: Edit Mode > Select > All by Trait > Non Manifold, then Face > Fill)";
  case Remedy::split_nonmanifold:
    return "let meromorph take them apart for the computation (--split-nonmanifold)";
  case Remedy::remove_zero_area_faces:
    return "meromorph param takes them out of the computation and keeps them in its outputs (to "
           "remove them: MeshLab: Filters > Cleaning and Repairing > Remove Zero Area Faces; "
           "Blender: Mesh > Clean Up > Degenerate Dissolve)";
  case Remedy::remove_duplicate_faces:
    return "remove the doubles (MeshLab: Filters > Cleaning and Repairing > Remove Duplicate "
           "Faces; Blender: Mesh > Clean Up > Merge by Distance)";
  case Remedy::remesh:
    return "remesh the surface (MeshLab: Filters > Remeshing, Simplification and Reconstruction "
           "> Remeshing: Isotropic Explicit Remeshing; Blender: Remesh modifier) and run again";
  case Remedy::refine:
    return "refine it (MeshLab: Filters > Remeshing, Simplification and Reconstruction > "
           "Subdivision Surfaces: Midpoint; Blender: Subdivide) and run again";
  case Remedy::generic_form_pair:
    return "use the default generic pair (--forms -1,-1)";
  case Remedy::shorten_thin_parts:
    return "shorten or thicken them, or map them separately";
  case Remedy::check_units:
    return "remove the stray vertex, or bring the coordinates to one unit";
  case Remedy::choose_uv_kind:
    return "use --pack-uv with --uv spherical (the default)";
  case Remedy::add_vertices:
    return "let meromorph add the vertices the map needs (run without --no-added-vertices and "
           "--strict)";
  }
  return "";
}

std::string with_remedies(const std::string &message, const std::vector<Remedy> &remedies) {
  std::string text = message;
  for (Remedy remedy : remedies)
    text += "; " + remedy_words(remedy);
  return text;
}

std::string advice_words(const std::vector<Advice> &advice) {
  std::vector<std::string> phrases;
  for (const Advice &a : advice)
    phrases.push_back(a.cause + ": " + remedy_words(a.remedy));
  return join_phrases(phrases);
}

} // namespace meromorph::cli
