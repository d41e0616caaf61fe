// Finding the triangles of a triangulated sphere that hold a point, at every scale at once.
//
// In:  points on the unit sphere and triangles on them (a map's image, a lifted sphere), and
//      which of the triangles to take.
// Out: `for_each_holding(p, visit)`: visit(f) for every taken triangle whose cone (from the
//      centre) holds the unit vector p, either orientation (a folded triangle too); and
//      `holding_with_weights(p)`: the first such triangle with the weights of its corners that
//      give p's direction (the ray from the centre through p crossing the flat triangle).
//      A triangle is kept in the cells of one level of a grid of cells of every size 2^-level:
//      the level whose cell is between half its bounding box and all of it (at most 27 cells),
//      so tiny triangles at a limb's image and large ones elsewhere are both found in a few
//      lookups. Triangles with a corner that is not finite are left out.
#pragma once

#include <array>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

namespace meromorph {

class SphereTriangleGrid {
public:
  SphereTriangleGrid(const std::vector<Eigen::Vector3d> &points,
                     const std::vector<std::array<int, 3>> &triangles,
                     const std::vector<int> &taken);
  // All triangles.
  SphereTriangleGrid(const std::vector<Eigen::Vector3d> &points,
                     const std::vector<std::array<int, 3>> &triangles);

  template <class Visit> void for_each_holding(const Eigen::Vector3d &p, Visit &&visit) const {
    if (!p.allFinite()) return;
    for (int level = 0; level <= max_level; ++level) {
      if (!used_[size_t(level)]) continue;
      const auto found = cells_.find(key(level, cell_of(p, cell_size(level))));
      if (found == cells_.end()) continue;
      for (int f : found->second)
        if (holds(f, p)) visit(f);
    }
  }

  struct Hold {
    int triangle = -1;                // -1: none holds p
    Eigen::Vector3d weights{0, 0, 0}; // of the triangle's corners, summing to 1
  };
  Hold holding_with_weights(const Eigen::Vector3d &p) const;
  // The weights of triangle f's corners that give p's direction (for a triangle for_each_holding
  // visited).
  Eigen::Vector3d weights_in(int f, const Eigen::Vector3d &p) const;

private:
  static constexpr int max_level = 50;
  using Cell = Eigen::Matrix<long long, 3, 1>;

  static double cell_size(int level);
  static Cell cell_of(const Eigen::Vector3d &point, double cell);
  static unsigned long long key(int level, const Cell &cell);
  bool holds(int f, const Eigen::Vector3d &p) const;
  void add(int f);

  const std::vector<Eigen::Vector3d> &points_;
  const std::vector<std::array<int, 3>> &triangles_;
  std::array<bool, max_level + 1> used_{};
  std::unordered_map<unsigned long long, std::vector<int>> cells_;
};

} // namespace meromorph
