#include "io/polygon_triangulation.h"

namespace meromorph {

void triangulate_polygon(const std::vector<int> &polygon, const std::vector<Point3> &positions,
                         std::vector<std::array<int, 3>> &triangles) {
  const size_t n = polygon.size();
  if (n == 3) {
    triangles.push_back({polygon[0], polygon[1], polygon[2]});
  } else if (n == 4) {
    const double diagonal02 = (positions[polygon[0]] - positions[polygon[2]]).SquaredNorm();
    const double diagonal13 = (positions[polygon[1]] - positions[polygon[3]]).SquaredNorm();
    if (diagonal02 <= diagonal13) {
      triangles.push_back({polygon[0], polygon[1], polygon[2]});
      triangles.push_back({polygon[0], polygon[2], polygon[3]});
    } else {
      triangles.push_back({polygon[0], polygon[1], polygon[3]});
      triangles.push_back({polygon[1], polygon[2], polygon[3]});
    }
  } else {
    for (size_t i = 1; i + 1 < n; ++i)
      triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
  }
}

} // namespace meromorph
