#include "io/polygon_triangulation.h"

#include <algorithm>

namespace meromorph {

bool PolygonTriangulation::made_by_another_quad(std::array<int, 3> triangle,
                                                const std::array<int, 4> &quad) const {
  std::sort(triangle.begin(), triangle.end());
  const auto made = quad_triangles_.find(triangle);
  return made != quad_triangles_.end() && made->second != quad;
}

void PolygonTriangulation::add_quad_triangle(const std::array<int, 3> &triangle,
                                             const std::array<int, 4> &quad) {
  triangles_.push_back(triangle);
  std::array<int, 3> sorted = triangle;
  std::sort(sorted.begin(), sorted.end());
  quad_triangles_.emplace(sorted, quad);
}

void PolygonTriangulation::finish(std::vector<int> &triangle_face,
                                  std::vector<std::string> &notes) const {
  if (split_polygons_ == 0) return;
  triangle_face = triangle_polygon_;
  notes.push_back("triangulated " + std::to_string(split_polygons_) + " polygonal faces into " +
                  std::to_string(triangles_.size()) + " triangles in all");
}

void PolygonTriangulation::add(const std::vector<int> &polygon) {
  const size_t n = polygon.size();
  split_polygons_ += n > 3;
  if (n == 3) {
    triangles_.push_back({polygon[0], polygon[1], polygon[2]});
  } else if (n == 4) {
    const std::array<std::array<int, 3>, 2> along02{
        {{polygon[0], polygon[1], polygon[2]}, {polygon[0], polygon[2], polygon[3]}}};
    const std::array<std::array<int, 3>, 2> along13{
        {{polygon[0], polygon[1], polygon[3]}, {polygon[1], polygon[2], polygon[3]}}};
    const double diagonal02 = (positions_[polygon[0]] - positions_[polygon[2]]).SquaredNorm();
    const double diagonal13 = (positions_[polygon[1]] - positions_[polygon[3]]).SquaredNorm();
    const bool shorter02 = diagonal02 <= diagonal13;
    const auto &first = shorter02 ? along02 : along13, &other = shorter02 ? along13 : along02;
    std::array<int, 4> quad{polygon[0], polygon[1], polygon[2], polygon[3]};
    std::sort(quad.begin(), quad.end());
    const bool doubles =
        made_by_another_quad(first[0], quad) || made_by_another_quad(first[1], quad);
    const bool other_doubles =
        made_by_another_quad(other[0], quad) || made_by_another_quad(other[1], quad);
    for (const auto &triangle : doubles && !other_doubles ? other : first)
      add_quad_triangle(triangle, quad);
  } else {
    for (size_t i = 1; i + 1 < n; ++i)
      triangles_.push_back({polygon[0], polygon[i], polygon[i + 1]});
  }
  triangle_polygon_.resize(triangles_.size(), polygons_);
  ++polygons_;
}

} // namespace meromorph
