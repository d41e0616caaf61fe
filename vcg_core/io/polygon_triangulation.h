// Splitting polygonal faces into triangles.
//
// In:  the mesh positions and, one after another, polygons as vertex indices (3 or more, in
//      order).
// Out: triangles appended to `triangles`, with each polygon's orientation. A quad is split along
//      its shorter diagonal, unless that makes a triangle on the same three vertices as one an
//      earlier quad on other vertices made (two quads sharing three vertices, as modelling tools
//      write them around a pole): then along the other (a quad written twice is split the same
//      way twice: doubled faces); a larger polygon as a fan from its first vertex (exact for
//      convex polygons, which is what modelling tools write).
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace meromorph {

class PolygonTriangulation {
public:
  PolygonTriangulation(const std::vector<Point3> &positions,
                       std::vector<std::array<int, 3>> &triangles)
      : positions_(positions), triangles_(triangles) {}
  void add(const std::vector<int> &polygon);
  // When any polygon had more than three corners: per triangle, the polygon it came from (in
  // `triangle_face`), and a note saying so.
  void finish(std::vector<int> &triangle_face, std::vector<std::string> &notes) const;

private:
  // Whether a quad on other vertices than `quad` (sorted) made this triangle.
  bool made_by_another_quad(std::array<int, 3> triangle, const std::array<int, 4> &quad) const;
  void add_quad_triangle(const std::array<int, 3> &triangle, const std::array<int, 4> &quad);
  const std::vector<Point3> &positions_;
  std::vector<std::array<int, 3>> &triangles_;
  std::map<std::array<int, 3>, std::array<int, 4>> quad_triangles_; // sorted corners -> quad
  std::vector<int> triangle_polygon_;
  int polygons_ = 0, split_polygons_ = 0;
};

} // namespace meromorph
