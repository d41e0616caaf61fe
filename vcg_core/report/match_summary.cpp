#include "report/match_summary.h"

#include <sstream>

namespace meromorph {

std::string match_summary(const SurfaceMatch &match, size_t landmark_count) {
  std::ostringstream words;
  words << "matched mesh: angle error " << match.angle_error_mean_degrees << " deg, "
        << match.folded_faces << " folded faces";
  if (landmark_count > 0)
    words << ", landmarks within " << 100 * match.landmark_residual_max << "% of the diagonal";
  if (match.unmatched_vertices > 0)
    words << ", " << match.unmatched_vertices << " vertices not matched";
  const size_t alternatives =
      match.genus == 1 ? match.torus.alternatives.size() : match.alignment.alternatives.size();
  if (alternatives > 0)
    words << "; " << alternatives
          << " other alignments fit almost as well (a symmetric surface: give landmarks)";
  return words.str();
}

} // namespace meromorph
