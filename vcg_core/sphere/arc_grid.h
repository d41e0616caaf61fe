// Which great-circle arcs a short path on the unit sphere may meet, looked up by where it starts.
//
// In:  arcs on the unit sphere (minor arcs between unit vectors) and the longest path to be looked
//      up (a chord length).
// Out: `near(x)`: the arcs that a path from x of at most that chord can meet (all others cannot),
//      in increasing order. A grid of cells over the cube [-1, 1]^3 lists per cell the arcs whose
//      reach meets it: a point z on the arc from p to q lies within |m - p| of its midpoint m, and
//      a point of the path from x to y within |x - y| of x, so where they meet, |m - x| is at most
//      the sum of the two chords.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

namespace meromorph {

class ArcGrid {
public:
  ArcGrid(const std::vector<Eigen::Vector3d> &ends, const std::vector<std::array<int, 2>> &arcs,
          double longest_path);

  const std::vector<int> &near(const Eigen::Vector3d &x) const { return cells_[cell_of(x)]; }

private:
  static constexpr int side = 20; // cells per axis
  static int axis_cell(double coordinate);
  static size_t cell_at(int x, int y, int z) {
    return size_t(x) + size_t(side) * size_t(y) + size_t(side) * size_t(side) * size_t(z);
  }
  static size_t cell_of(const Eigen::Vector3d &x) {
    return cell_at(axis_cell(x.x()), axis_cell(x.y()), axis_cell(x.z()));
  }
  std::vector<std::vector<int>> cells_;
};

} // namespace meromorph
