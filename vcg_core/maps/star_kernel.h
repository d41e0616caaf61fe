// The point of a star's kernel farthest inside it: where a vertex goes so that none of its faces
// is turned over.
//
// In:  a vertex's one-ring, in order (faces (vertex, ring[j], ring[j + 1]) counter-clockwise
//      when none is turned over), as points of a plane chart.
// Out: the point p that maximises the smallest distance, measured inwards, from p to the lines
//      through the ring's sides (the Chebyshev centre of the kernel: every face (p, ring[j],
//      ring[j + 1]) then turns counter-clockwise by that margin), and that distance; nothing
//      where no point is inside every side (the ring winds around no point once), or for fewer
//      than three points. Exact over the few sides a ring has (every three sides' common point
//      is tried).
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace meromorph {

std::optional<std::pair<Eigen::Vector2d, double>>
star_kernel_centre(const std::vector<Eigen::Vector2d> &ring);

} // namespace meromorph
