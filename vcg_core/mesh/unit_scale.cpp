#include "mesh/unit_scale.h"

#include <algorithm>
#include <cmath>

#include "mesh/mesh_from_arrays.h"

namespace meromorph {

Point3 UnitScale::apply(const Point3 &position) const {
  Point3 out;
  // Halve before subtracting: x - c cannot overflow even for coordinates near the largest double.
  for (int k = 0; k < 3; ++k)
    out[k] = std::ldexp(std::ldexp(position[k], -1) - std::ldexp(centre[k], -1), exponent + 1);
  return out;
}

Point3 UnitScale::undo(const Point3 &unit) const {
  Point3 out;
  for (int k = 0; k < 3; ++k)
    out[k] = std::ldexp(unit[k], -exponent) + centre[k];
  return out;
}

UnitScale unit_scale_of(const Mesh &mesh) {
  UnitScale scale;
  if (mesh.vert.empty()) return scale;
  Point3 low = mesh.vert[0].cP(), high = low;
  for (const MeshVertex &vertex : mesh.vert)
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], vertex.cP()[k]);
      high[k] = std::max(high[k], vertex.cP()[k]);
    }
  double half_extent = 0; // the largest |coordinate - centre|, halved against overflow
  for (int k = 0; k < 3; ++k) {
    scale.centre[k] = std::ldexp(low[k], -1) + std::ldexp(high[k], -1);
    half_extent = std::max(half_extent, std::ldexp(high[k], -2) - std::ldexp(low[k], -2));
  }
  if (half_extent > 0 && std::isfinite(half_extent)) {
    int exponent = 0;
    std::frexp(half_extent, &exponent); // half_extent = m 2^exponent, m in [0.5, 1)
    scale.exponent = -(exponent + 1);
  }
  return scale;
}

bool is_at_unit_scale(const Mesh &mesh) {
  const UnitScale scale = unit_scale_of(mesh);
  return scale.exponent == 0 && scale.centre.Norm() < 1e-3;
}

void copy_at_unit_scale(const Mesh &mesh, const UnitScale &scale, Mesh &unit) {
  MeshArrays arrays = arrays_from_mesh(mesh);
  for (Point3 &position : arrays.positions)
    position = scale.apply(position);
  mesh_from_arrays(arrays, unit);
}

UnitScaleInPlace::UnitScaleInPlace(Mesh &mesh) : mesh_(mesh) {
  const UnitScale scale = unit_scale_of(mesh);
  original_.reserve(mesh.vert.size());
  for (MeshVertex &vertex : mesh.vert) {
    original_.push_back(vertex.cP());
    vertex.P() = scale.apply(vertex.cP());
  }
}

UnitScaleInPlace::~UnitScaleInPlace() {
  for (size_t v = 0; v < original_.size(); ++v)
    mesh_.vert[v].P() = original_[v];
}

} // namespace meromorph
