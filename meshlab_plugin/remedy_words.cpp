#include "remedy_words.h"

#include "meromorph.h"

QString meshlab_remedy_words(int remedy) {
  switch (remedy) {
  case MEROMORPH_REMEDY_REPAIR:
    return "Filters > Cleaning and Repairing > Merge Close Vertices and Remove Unreferenced "
           "Vertices, then Filters > Normals, Curvatures and Orientation > Re-Orient all faces "
           "coherentely, fix it";
  case MEROMORPH_REMEDY_CLOSE_HOLES:
    return "tick 'Close holes' in this filter's parameters, or close them (Filters > Remeshing, "
           "Simplification and Reconstruction > Close Holes)";
  case MEROMORPH_REMEDY_SPLIT_NONMANIFOLD:
    return "tick 'Split non-manifold spots' in this filter's parameters";
  case MEROMORPH_REMEDY_REMOVE_ZERO_AREA_FACES:
    return "they are kept out of the computation (to remove them: Filters > Cleaning and "
           "Repairing > Remove Zero Area Faces)";
  case MEROMORPH_REMEDY_REMOVE_DUPLICATE_FACES:
    return "remove the doubles (Filters > Cleaning and Repairing > Remove Duplicate Faces)";
  case MEROMORPH_REMEDY_REMESH:
    return "remesh the surface (Filters > Remeshing, Simplification and Reconstruction > "
           "Remeshing: Isotropic Explicit Remeshing) and run again";
  case MEROMORPH_REMEDY_REFINE:
    return "refine it (Filters > Remeshing, Simplification and Reconstruction > Subdivision "
           "Surfaces: Midpoint) and run again";
  case MEROMORPH_REMEDY_GENERIC_FORM_PAIR:
    return "set 'Genus >= 2: first form' and 'second form' to -1 (a generic pair)";
  case MEROMORPH_REMEDY_SHORTEN_THIN_PARTS:
    return "shorten or thicken them, or map them as separate layers";
  case MEROMORPH_REMEDY_CHECK_UNITS:
    return "remove the stray vertex, or bring the coordinates to one unit (Filters > Normals, "
           "Curvatures and Orientation > Transform: Scale)";
  case MEROMORPH_REMEDY_CHOOSE_UV_KIND:
    return "choose 'Spherical' texture coordinates to pack the parts' texture coordinates";
  case MEROMORPH_REMEDY_ADD_VERTICES:
    return "tick 'Add vertices where needed' (and untick 'Strict') in this filter's parameters";
  default:
    return "";
  }
}

QString with_meshlab_remedies(const QString &message, const std::vector<int> &remedies) {
  QString text = message;
  for (int remedy : remedies)
    text += "; " + meshlab_remedy_words(remedy);
  return text;
}

QString meshlab_advice_words(const std::vector<QString> &causes, const std::vector<int> &remedies) {
  QString text;
  for (size_t i = 0; i < causes.size() && i < remedies.size(); ++i)
    text += (i ? "; " : "") + causes[i] + ": " + meshlab_remedy_words(remedies[i]);
  return text;
}
