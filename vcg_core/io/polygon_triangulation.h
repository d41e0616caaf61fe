// Splitting a polygonal face into triangles.
//
// In:  the polygon's vertex indices (3 or more, in order) and the mesh positions.
// Out: triangles appended to `triangles`, with the polygon's orientation. A quad is split along
//      its shorter diagonal; a larger polygon as a fan from its first vertex (exact for convex
//      polygons, which is what modelling tools write).
#pragma once

#include <array>
#include <vector>

#include "mesh/mesh.h"

namespace meromorph {

void triangulate_polygon(const std::vector<int> &polygon, const std::vector<Point3> &positions,
                         std::vector<std::array<int, 3>> &triangles);

} // namespace meromorph
