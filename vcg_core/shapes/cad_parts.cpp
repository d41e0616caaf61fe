#include "shapes/cad_parts.h"

#include <array>
#include <cmath>
#include <vector>

#include "common/errors.h"
#include "mesh/mesh_from_arrays.h"

namespace meromorph {
namespace {

using Triangle = std::array<int, 3>;

// Top and bottom faces as the same triangles (the bottom's reversed), the walls between their
// boundaries' corresponding vertices (`layer`: the bottom's vertex = the top's + layer).
void add_faces_and_walls(const std::vector<Triangle> &top,
                         const std::vector<std::array<int, 2>> &wall, int layer,
                         MeshArrays &arrays) {
  for (const Triangle &t : top) {
    arrays.triangles.push_back(t);
    arrays.triangles.push_back({t[0] + layer, t[2] + layer, t[1] + layer});
  }
  // Each wall side a -> b seen from above with the part on its left: two triangles outward.
  for (const auto &side : wall) {
    const int a = side[0], b = side[1];
    arrays.triangles.push_back({a + layer, b + layer, b});
    arrays.triangles.push_back({a + layer, b, a});
  }
}

void make_cylinder(int segments, double height, MeshArrays &arrays) {
  std::vector<Triangle> top;
  std::vector<std::array<int, 2>> wall;
  for (int k = 0; k < segments; ++k) {
    const double angle = 2 * M_PI * k / segments;
    arrays.positions.emplace_back(std::cos(angle), std::sin(angle), height);
    wall.push_back({k, (k + 1) % segments});
  }
  for (int k = 1; k + 1 < segments; ++k) // the cap fanned from its first rim vertex
    top.push_back({0, k, k + 1});
  for (int k = 0; k < segments; ++k)
    arrays.positions.push_back(arrays.positions[size_t(k)] - Point3(0, 0, height));
  add_faces_and_walls(top, wall, segments, arrays);
}

void make_plate(int holes, int segments, double thickness, MeshArrays &arrays) {
  // The squares' corners (i, 0) and (i, 1), then each hole's circle.
  auto corner = [](int i, int j) { return 2 * i + j; };
  for (int i = 0; i <= holes; ++i)
    for (int j = 0; j < 2; ++j)
      arrays.positions.emplace_back(i, j, thickness);
  auto circle = [&](int hole, int k) {
    return 2 * (holes + 1) + hole * segments + (k + segments) % segments;
  };
  std::vector<Triangle> top;
  std::vector<std::array<int, 2>> wall;
  for (int hole = 0; hole < holes; ++hole) {
    // The square's corner nearest each circle point: quarter q of the circle faces corner q.
    const std::array<int, 4> nearest{corner(hole + 1, 1), corner(hole, 1), corner(hole, 0),
                                     corner(hole + 1, 0)};
    for (int k = 0; k < segments; ++k) {
      const double angle = 2 * M_PI * (k + 0.5) / segments;
      arrays.positions.emplace_back(hole + 0.5 + 0.3 * std::cos(angle), 0.5 + 0.3 * std::sin(angle),
                                    thickness);
      wall.push_back({circle(hole, k + 1), circle(hole, k)});
    }
    for (int k = 0; k < segments; ++k) {
      const int here = nearest[size_t(4 * k / segments)];
      const int next = nearest[size_t((4 * (k + 1) / segments) % 4)];
      if (here != next) top.push_back({circle(hole, k), here, next});
      top.push_back({circle(hole, k), next, circle(hole, k + 1)});
    }
  }
  for (int i = 0; i < holes; ++i) { // the outline, counter-clockwise seen from above
    wall.push_back({corner(i, 0), corner(i + 1, 0)});
    wall.push_back({corner(i + 1, 1), corner(i, 1)});
  }
  wall.push_back({corner(holes, 0), corner(holes, 1)});
  wall.push_back({corner(0, 1), corner(0, 0)});
  const int layer = int(arrays.positions.size());
  for (int v = 0; v < layer; ++v)
    arrays.positions.push_back(arrays.positions[size_t(v)] - Point3(0, 0, thickness));
  add_faces_and_walls(top, wall, layer, arrays);
}

} // namespace

void make_cad_part(Mesh &mesh, int holes, int segments, double thickness) {
  if (holes < 0 || holes > 100) throw ArgumentError("the holes must be from 0 to 100");
  if (segments < 8 || segments > 100000 || (holes > 0 && segments % 4 != 0))
    throw ArgumentError("the segments must be from 8 to 100000, and a multiple of 4 with holes");
  if (!(thickness > 0 && thickness <= 100))
    throw ArgumentError("the thickness must be in (0, 100]");
  MeshArrays arrays;
  if (holes == 0)
    make_cylinder(segments, thickness, arrays);
  else
    make_plate(holes, segments, thickness, arrays);
  mesh_from_arrays(arrays, mesh);
}

} // namespace meromorph
