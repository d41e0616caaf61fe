// Distances between triangle meshes, with geometry of the tests' own (nothing from the core or
// vcglib), for judging a written remesh against its input.
//
// In:  a triangle mesh (positions and triangles) to measure against; query points.
// Out: `NearestOnSurface`: for a point, the distance to the nearest point of the mesh and the
//      unit normal of the triangle it lies on (a uniform grid of the triangles' bounding boxes,
//      searched ring by ring until no nearer triangle can be left).
#pragma once

#include <array>
#include <unordered_map>
#include <vector>

#include "vector3.h"

namespace meromorph::test {

class NearestOnSurface {
public:
  NearestOnSurface(const std::vector<Vec3> &positions,
                   const std::vector<std::array<int, 3>> &triangles);
  struct Nearest {
    double distance = 0;
    Vec3 normal{};
  };
  Nearest operator()(const Vec3 &point) const;
  double diagonal() const { return diagonal_; }

private:
  long long cell_key(long long i, long long j, long long k) const;
  const std::vector<Vec3> &positions_;
  const std::vector<std::array<int, 3>> &triangles_;
  Vec3 low_{};
  double cell_ = 1, diagonal_ = 0;
  std::array<long long, 3> cells_{};
  std::unordered_map<long long, std::vector<int>> grid_;
};

} // namespace meromorph::test
