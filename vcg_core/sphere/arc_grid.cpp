#include "sphere/arc_grid.h"

#include <algorithm>
#include <cmath>

namespace meromorph {

int ArcGrid::axis_cell(double coordinate) {
  if (!std::isfinite(coordinate)) return 0; // (meets no arc anyway)
  return std::clamp(int(std::floor((coordinate + 1.0) * 0.5 * side)), 0, side - 1);
}

ArcGrid::ArcGrid(const std::vector<Eigen::Vector3d> &ends,
                 const std::vector<std::array<int, 2>> &arcs, double longest_path)
    : cells_(size_t(side) * side * side) {
  const double cell = 2.0 / side;
  for (size_t a = 0; a < arcs.size(); ++a) {
    const Eigen::Vector3d &p = ends[size_t(arcs[a][0])], &q = ends[size_t(arcs[a][1])];
    const Eigen::Vector3d sum = p + q;
    // Nearly opposite ends (no minor arc to speak of): the arc is near everywhere.
    const double norm = sum.norm();
    const Eigen::Vector3d middle =
        norm > 1e-6 ? Eigen::Vector3d(sum / norm) : Eigen::Vector3d::Zero();
    // (The margin covers rounding, as of points a little off the sphere or the grid.)
    const double reach = norm > 1e-6 ? (middle - p).norm() + longest_path + 1e-9 : 4.0;
    std::array<int, 3> low, high;
    for (int k = 0; k < 3; ++k) {
      low[size_t(k)] = axis_cell(middle[k] - reach);
      high[size_t(k)] = axis_cell(middle[k] + reach);
    }
    for (int z = low[2]; z <= high[2]; ++z)
      for (int y = low[1]; y <= high[1]; ++y)
        for (int x = low[0]; x <= high[0]; ++x) {
          // The distance from the middle to the cell's box.
          const Eigen::Vector3d lower(-1 + x * cell, -1 + y * cell, -1 + z * cell);
          const Eigen::Vector3d nearest =
              middle.cwiseMax(lower).cwiseMin(lower + Eigen::Vector3d::Constant(cell));
          if ((nearest - middle).norm() <= reach) cells_[cell_at(x, y, z)].push_back(int(a));
        }
  }
}

} // namespace meromorph
