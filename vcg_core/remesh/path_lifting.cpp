#include "remesh/path_lifting.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace meromorph {
namespace {

// det(x, p, q) = x . (p x q), computed from the differences p - x and q - x, so that it keeps its
// relative precision for points a hair apart (a long part's image, 1e-8 across and less, where
// p x q alone is rounding).
double det(const Eigen::Vector3d &x, const Eigen::Vector3d &p, const Eigen::Vector3d &q) {
  return x.dot((p - x).cross(q - x));
}

// Rounding in det(x, s, r): a few hundred ulps of its terms.
double side_tolerance(const Eigen::Vector3d &x, const Eigen::Vector3d &s,
                      const Eigen::Vector3d &r) {
  return 1e-13 * (s - x).norm() * (r - x).norm();
}

// Barycentric coordinates of the value x in face f's image (the central projection of x onto the
// image triangle's plane), negative outside.
Eigen::Vector3d image_weights(const MappedSurface &surface, int f, const Eigen::Vector3d &x) {
  const auto &c = surface.faces[f];
  const Eigen::Vector3d &s0 = surface.image[c[0]], &s1 = surface.image[c[1]],
                        &s2 = surface.image[c[2]];
  Eigen::Vector3d w(det(x, s1, s2), det(s0, x, s2), det(s0, s1, x));
  const double sum = w.sum();
  return std::abs(sum) > 1e-300 ? Eigen::Vector3d(w / sum) : Eigen::Vector3d(1, 0, 0);
}

SurfacePoint settled(const MappedSurface &surface, int f, const Eigen::Vector3d &x) {
  Eigen::Vector3d w = image_weights(surface, f, x).cwiseMax(0.0);
  const double sum = w.sum();
  return {f, sum > 0 ? Eigen::Vector3d(w / sum) : Eigen::Vector3d(1, 0, 0)};
}

} // namespace

Eigen::Vector3d position_of(const MappedSurface &surface, const SurfacePoint &point) {
  const auto &c = surface.faces[point.face];
  return point.weights[0] * surface.positions[c[0]] + point.weights[1] * surface.positions[c[1]] +
         point.weights[2] * surface.positions[c[2]];
}

std::vector<SurfacePoint> points_over(const MappedSurface &surface, const Eigen::Vector3d &q) {
  std::vector<SurfacePoint> found;
  std::vector<Eigen::Vector3d> where;
  for (int f = 0; f < int(surface.faces.size()); ++f) {
    const auto &c = surface.faces[f];
    const Eigen::Vector3d &s0 = surface.image[c[0]], &s1 = surface.image[c[1]],
                          &s2 = surface.image[c[2]];
    if (det(s0, s1, s2) <= 0 || (s0 + s1 + s2).dot(q) <= 0) continue;
    if (det(s0, s1, q) < 0 || det(s1, s2, q) < 0 || det(s2, s0, q) < 0) continue;
    const SurfacePoint point = settled(surface, f, q);
    const Eigen::Vector3d p = position_of(surface, point);
    bool seen = false;
    for (const Eigen::Vector3d &other : where)
      seen |= (other - p).squaredNorm() < 1e-24;
    if (seen) continue;
    found.push_back(point);
    where.push_back(p);
  }
  return found;
}

std::optional<SurfacePoint> lift_arc(const MappedSurface &surface, const SurfacePoint &start,
                                     const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                                     int max_steps, std::vector<PathPoint> *path,
                                     PathPoint *boundary_exit) {
  if (boundary_exit) boundary_exit->point.face = -1;
  // The chord x(t) = (1 - t) a + t b projects onto the arc; side k of a face is crossed where
  // det(s_k, s_k+1, x(t)), linear in t, turns negative. The lift leaves each face by the side
  // crossed first and enters the face across it.
  int face = start.face, came_from = -1;
  double t = 0;
  for (int step = 0; step < max_steps; ++step) {
    const auto &c = surface.faces[face];
    int exit = -1;
    double exit_t = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d &s = surface.image[c[k]], &r = surface.image[c[(k + 1) % 3]];
      const double at_a = det(a, s, r), at_b = det(b, s, r);
      // b on the inner side of this side, or on its great circle up to rounding (b at one of the
      // side's ends, a branch value, gives a determinant of rounding noise either sign).
      if (at_b >= -side_tolerance(b, s, r)) continue;
      if (surface.across[face][k] == came_from && came_from >= 0) continue;
      const double crossing = at_a > at_b ? at_a / (at_a - at_b) : t;
      if (crossing < exit_t) {
        exit_t = crossing;
        exit = k;
      }
    }
    if (exit < 0) {
      const SurfacePoint end = settled(surface, face, b);
      if (path) path->push_back({end, 1.0});
      return end;
    }
    const int next = surface.across[face][exit];
    if (next < 0) {
      if (boundary_exit) {
        const double at = std::clamp(exit_t, t, 1.0);
        *boundary_exit = {settled(surface, face, (1 - at) * a + at * b), at};
      }
      return std::nullopt;
    }
    came_from = face;
    face = next;
    t = std::max(t, exit_t);
    if (path) path->push_back({settled(surface, face, (1 - t) * a + t * b), t});
  }
  return std::nullopt;
}

} // namespace meromorph
