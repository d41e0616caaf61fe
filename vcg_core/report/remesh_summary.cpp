#include "report/remesh_summary.h"

#include <iomanip>
#include <sstream>

namespace meromorph {

std::string remesh_summary(const std::string &input, const Parameterization &map,
                           const SurfaceRemesh &remesh) {
  const RemeshQuality &q = remesh.quality;
  std::ostringstream line;
  line << std::fixed << std::setprecision(2) << input << ": remeshed through " << map.degree
       << (map.degree == 1 ? " layer" : " layers") << ": " << q.vertices << " vertices (target "
       << remesh.target_vertices << "), " << q.faces << " faces, Euler characteristic " << q.euler
       << " (input " << map.euler << (map.holes_closed.empty() ? "" : " with its holes closed")
       << "); Hausdorff distance " << std::setprecision(3) << 100 * q.hausdorff_to_input << "% / "
       << 100 * q.hausdorff_from_input << "% of the diagonal; angles min " << std::setprecision(1)
       << q.min_angle_degrees << " (away from branch vertices "
       << q.min_angle_away_from_branch_degrees << "), mean " << q.mean_angle_degrees
       << " deg; folded lifts " << remesh.folded_lifts;
  if (remesh.unlifted_faces) line << "; faces not lifted " << remesh.unlifted_faces;
  if (map.area_correction.applied)
    line << "; area distortion " << std::setprecision(3) << map.area_correction.distortion_before
         << " -> " << map.area_correction.distortion_after;
  return line.str();
}

} // namespace meromorph
