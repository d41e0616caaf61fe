#include "sphere/sphere_triangle_grid.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace meromorph {

SphereTriangleGrid::SphereTriangleGrid(const std::vector<Eigen::Vector3d> &points,
                                       const std::vector<std::array<int, 3>> &triangles,
                                       const std::vector<int> &taken)
    : points_(points), triangles_(triangles) {
  for (int f : taken)
    add(f);
}

SphereTriangleGrid::SphereTriangleGrid(const std::vector<Eigen::Vector3d> &points,
                                       const std::vector<std::array<int, 3>> &triangles)
    : points_(points), triangles_(triangles) {
  for (size_t f = 0; f < triangles.size(); ++f)
    add(int(f));
}

void SphereTriangleGrid::add(int f) {
  const auto &triangle = triangles_[size_t(f)];
  const Eigen::Vector3d &a = points_[size_t(triangle[0])], &b = points_[size_t(triangle[1])],
                        &c = points_[size_t(triangle[2])];
  // The spherical triangle lies within 1 - h of the flat one (h: the plane's distance from the
  // centre).
  const Eigen::Vector3d normal = (b - a).cross(c - a);
  const double norm = normal.norm();
  const double bulge = norm > 0 ? 1.0 - std::abs(normal.dot(a)) / norm : 1.0;
  const Eigen::Vector3d low = a.cwiseMin(b).cwiseMin(c).array() - bulge,
                        high = a.cwiseMax(b).cwiseMax(c).array() + bulge;
  if (!low.allFinite() || !high.allFinite()) return; // a corner that is not on the sphere
  const double size = std::max((high - low).maxCoeff(), 1e-300);
  const int level = std::clamp(int(std::floor(std::log2(1.0 / size))) + 1, 0, max_level);
  used_[size_t(level)] = true;
  const double cell = cell_size(level);
  const Cell from = cell_of(low, cell), to = cell_of(high, cell);
  for (long long i = from.x(); i <= to.x(); ++i)
    for (long long j = from.y(); j <= to.y(); ++j)
      for (long long k = from.z(); k <= to.z(); ++k)
        cells_[key(level, {i, j, k})].push_back(f);
}

double SphereTriangleGrid::cell_size(int level) {
  return std::ldexp(1.0, -level);
}

SphereTriangleGrid::Cell SphereTriangleGrid::cell_of(const Eigen::Vector3d &point, double cell) {
  return {(long long)std::floor((point.x() + 2.0) / cell),
          (long long)std::floor((point.y() + 2.0) / cell),
          (long long)std::floor((point.z() + 2.0) / cell)};
}

// A cell of a level (counted from a corner of [-2, 2]^3) as one number for the hash map.
unsigned long long SphereTriangleGrid::key(int level, const Cell &cell) {
  unsigned long long h = (unsigned long long)level;
  for (int k = 0; k < 3; ++k)
    h = h * 0x9E3779B97F4A7C15ULL + (unsigned long long)cell[k];
  return h;
}

// Inside the cone of the triangle, either orientation.
bool SphereTriangleGrid::holds(int f, const Eigen::Vector3d &p) const {
  const auto &triangle = triangles_[size_t(f)];
  const Eigen::Vector3d &a = points_[size_t(triangle[0])], &b = points_[size_t(triangle[1])],
                        &c = points_[size_t(triangle[2])];
  if (p.dot(a + b + c) <= 0) return false;
  // det(a, b, p) as p . ((a - p) x (b - p)): precise where the triangle is a hair across.
  const Eigen::Vector3d pa = a - p, pb = b - p, pc = c - p;
  const double ab = p.dot(pa.cross(pb)), bc = p.dot(pb.cross(pc)), ca = p.dot(pc.cross(pa));
  return (ab >= 0 && bc >= 0 && ca >= 0) || (ab <= 0 && bc <= 0 && ca <= 0);
}

SphereTriangleGrid::Hold SphereTriangleGrid::holding_with_weights(const Eigen::Vector3d &p) const {
  Hold hold;
  for_each_holding(p, [&](int f) {
    if (hold.triangle >= 0) return;
    hold.triangle = f;
    hold.weights = weights_in(f, p);
  });
  return hold;
}

Eigen::Vector3d SphereTriangleGrid::weights_in(int f, const Eigen::Vector3d &p) const {
  const auto &triangle = triangles_[size_t(f)];
  const Eigen::Vector3d &a = points_[size_t(triangle[0])], &b = points_[size_t(triangle[1])],
                        &c = points_[size_t(triangle[2])];
  // Volumes of the tetrahedra (0, p, ., .): the weights of the ray's crossing of the triangle.
  const Eigen::Vector3d pa = a - p, pb = b - p, pc = c - p;
  const Eigen::Vector3d w(std::abs(p.dot(pb.cross(pc))), std::abs(p.dot(pc.cross(pa))),
                          std::abs(p.dot(pa.cross(pb))));
  const double sum = w.sum();
  return sum > 0 ? Eigen::Vector3d(w / sum) : Eigen::Vector3d(1, 0, 0);
}

} // namespace meromorph
