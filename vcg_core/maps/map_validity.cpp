#include "maps/map_validity.h"

#include <cmath>
#include <sstream>

#include "common/errors.h"
#include "common/wording.h"
#include "mesh/face_vectors.h"

namespace meromorph {

std::vector<std::string> invalid_reasons(const ParameterizeOptions &options,
                                         const Parameterization &map) {
  std::vector<std::string> reasons;
  const int expected = map.genus == 0 ? 1 : map.genus == 1 ? 2 : 2 * map.genus - 2;
  const bool chosen_pair = map.genus >= 2 && options.form_pair[0] >= 0;
  if (chosen_pair ? (map.degree < 1 || map.degree > expected) : map.degree != expected)
    reasons.push_back("the map covers the sphere " + std::to_string(map.degree) +
                      " times instead of " + std::to_string(expected));
  // Where faces shrink below what doubles resolve, the windings around them cannot be measured:
  // a count that does not add up says nothing of branch points there.
  const size_t collapsed = map.quality.collapsed_face_indices.size();
  if (!map.riemann_hurwitz_ok)
    reasons.push_back(
        "Riemann-Hurwitz does not hold (chi = " + std::to_string(map.euler) +
        ", 2 * degree - ramification = " + std::to_string(2 * map.degree - map.ramification) +
        (collapsed > 0 ? "): the windings around the parts that shrink below double precision "
                         "cannot be measured"
                       : "): branch points were missed or are wrong"));
  const std::vector<int> &folded = map.quality.folded_face_indices;
  if (!folded.empty())
    reasons.push_back(folded.size() == 1
                          ? "1 face is turned over (face " + list_indices(folded) + ")"
                          : std::to_string(folded.size()) + " faces are turned over (faces " +
                                list_indices(folded) + ")");
  // Where faces shrink below what doubles resolve, that is the cause of the rest: said first.
  if (!reasons.empty() && collapsed > 0)
    reasons.insert(reasons.begin(), plural(collapsed, "face shrinks", "faces shrink") +
                                        " below what double precision resolves (long "
                                        "thin parts: see below)");
  return reasons;
}

std::vector<Advice> invalid_map_advice(const std::vector<Point3> &input_positions, const Mesh &mesh,
                                       const ParameterizeOptions &options,
                                       const Parameterization &map) {
  std::vector<Advice> advice;
  const std::vector<int> &collapsed = map.quality.collapsed_face_indices;
  if (!collapsed.empty()) {
    const Point3 &at =
        input_positions[size_t(index_of(mesh, mesh.face[size_t(collapsed.front())].cV(0)))];
    std::ostringstream where;
    where << " (faces " << list_indices(collapsed) << "; the first at " << at[0] << ", " << at[1]
          << ", " << at[2] << ")";
    advice.push_back({plural(collapsed.size(), "face maps", "faces map") +
                          " to spots smaller than double precision resolves" + where.str() +
                          ": long thin parts shrink exponentially under a conformal map",
                      Remedy::shorten_thin_parts});
  }
  int needles = 0;
  for (const MeshFace &face : mesh.face)
    needles += smallest_angle(face) < M_PI / 180;
  if (needles > 0)
    advice.push_back(
        {plural(size_t(needles), "face has", "faces have") + " an angle below 1 degree",
         Remedy::remesh});
  if (map.genus >= 2 && options.form_pair[0] >= 0)
    advice.push_back({"the chosen form pair may be nearly 0 / 0 on parts of this surface",
                      Remedy::generic_form_pair});
  if (advice.empty())
    advice.push_back({"the mesh may be too coarse near the branch points", Remedy::refine});
  return advice;
}

} // namespace meromorph
