// Following the sheets of a branched cover across a surface: every vertex of one surface has
// several candidate points on another (the preimages of its image, one per sheet); choose one per
// vertex so that neighbours' choices stay close, which keeps a whole region on one sheet.
//
// In:  per vertex its candidates (points of the other surface; may be none), the vertices next to
//      each vertex, and a seed vertex with its chosen candidate.
// Out: per vertex the index of its chosen candidate, -1 where it has none or is not reached.
//      Grown from the seed clearest first: of the vertices next to decided ones, the one whose
//      candidates are farthest apart is decided next, taking the candidate nearest the mean of its
//      decided neighbours' choices; vertices near a branch point (where the sheets meet and the
//      candidates close up) come last, surrounded by decided ones.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace meromorph {

std::vector<int> follow_sheets(const std::vector<std::vector<Eigen::Vector3d>> &candidates,
                               const std::vector<std::vector<int>> &neighbours, int seed,
                               int seed_choice);

} // namespace meromorph
