// The words of a match's summary line, shared by `match` and `transfer`.
//
// In:  a SurfaceMatch and how many landmark pairs it was given.
// Out: "matched mesh: angle error A deg, F folded faces[, landmarks within L% of the diagonal]
//      [, N vertices not matched][; K other alignments fit almost as well (...)]".
#pragma once

#include <string>

#include "match/surface_match.h"

namespace meromorph {

std::string match_summary(const SurfaceMatch &match, size_t landmark_count);

} // namespace meromorph
