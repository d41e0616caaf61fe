#include "remesh/lifted_relaxation.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/LU>

namespace meromorph {
namespace {

constexpr double kept_angle = 35.0 * M_PI / 180.0;

struct Star {
  std::vector<int> faces, neighbours;
};

std::vector<Star> stars_of(const LiftedSphere &lifted) {
  std::vector<Star> stars(lifted.positions.size());
  for (size_t f = 0; f < lifted.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      Star &star = stars[lifted.faces[f][k]];
      star.faces.push_back(int(f));
      for (int m = 1; m < 3; ++m)
        star.neighbours.push_back(lifted.faces[f][(k + m) % 3]);
    }
  for (Star &star : stars) {
    std::sort(star.neighbours.begin(), star.neighbours.end());
    star.neighbours.erase(std::unique(star.neighbours.begin(), star.neighbours.end()),
                          star.neighbours.end());
  }
  return stars;
}

// What the faces around a vertex look like: folded on the surface, turned over on the sphere,
// smallest corner angle.
struct StarShape {
  int folded = 0;
  bool turned_on_sphere = false;
  double smallest_angle = M_PI;
};

StarShape shape_of(const MappedSurface &surface, const LiftedSphere &lifted, const Star &star) {
  StarShape shape;
  for (int f : star.faces) {
    const auto &c = lifted.faces[f];
    shape.folded += lifted_face_folds(surface, lifted, c);
    shape.turned_on_sphere |= !positive_on_sphere(lifted, c);
    shape.smallest_angle = std::min(shape.smallest_angle, smallest_corner_angle(lifted, c));
  }
  return shape;
}

bool better_or_fine(const StarShape &before, const StarShape &after) {
  if (after.turned_on_sphere || after.folded > before.folded) return false;
  if (after.folded < before.folded) return true;
  return after.smallest_angle >= std::min(before.smallest_angle, kept_angle);
}

// The sphere value whose lift is nearest the middle of the vertex's faces, to first order.
Eigen::Vector3d relaxed_value(const LiftedSphere &lifted, int v, const Star &star) {
  const Eigen::Vector3d &s = lifted.sphere[v], &p = lifted.positions[v];
  const Eigen::Vector3d e1 = s.unitOrthogonal(), e2 = s.cross(e1);
  Eigen::Matrix2d tt = Eigen::Matrix2d::Zero();
  Eigen::Matrix<double, 3, 2> pt = Eigen::Matrix<double, 3, 2>::Zero();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double nearest = 1e300;
  for (int u : star.neighbours) {
    const Eigen::Vector3d &su = lifted.sphere[u];
    const double along = su.dot(s);
    if (along <= 0.5) return s; // a neighbour far round the sphere: leave the vertex be
    const Eigen::Vector2d t((su / along).dot(e1), (su / along).dot(e2));
    const Eigen::Vector3d d = lifted.positions[u] - p;
    nearest = std::min(nearest, t.norm());
    tt += t * t.transpose();
    pt += d * t.transpose();
  }
  // The area-weighted mean of the faces' centroids: vertices drift toward large faces, which
  // evens out the faces' sizes as well as their shapes.
  double area = 0;
  for (int f : star.faces) {
    const auto &c = lifted.faces[f];
    const Eigen::Vector3d &a = lifted.positions[c[0]], &b = lifted.positions[c[1]],
                          &d = lifted.positions[c[2]];
    const double face_area = 0.5 * (b - a).cross(d - a).norm();
    mean += face_area * (a + b + d) / 3.0;
    area += face_area;
  }
  if (area <= 0) return s;
  mean /= area;
  if (std::abs(tt.determinant()) < 1e-300) return s;
  const Eigen::Matrix<double, 3, 2> jacobian = pt * tt.inverse();
  const Eigen::Matrix2d normal = jacobian.transpose() * jacobian;
  if (std::abs(normal.determinant()) < 1e-300) return s;
  Eigen::Vector2d step = normal.inverse() * (jacobian.transpose() * (mean - p));
  // No further than halfway to the nearest neighbour on the sphere.
  if (step.norm() > 0.5 * nearest) step *= 0.5 * nearest / step.norm();
  return (s + step.x() * e1 + step.y() * e2).normalized();
}

} // namespace

void relax_lifted_sphere(const MappedSurface &surface, const std::vector<int> &face_layer,
                         int rounds, LiftedSphere &lifted) {
  const std::vector<Star> stars = stars_of(lifted);
  constexpr int max_steps = 256; // a short move crosses few faces
  for (int round = 0; round < rounds; ++round) {
    for (size_t v = 0; v < lifted.positions.size(); ++v) {
      const Star &star = stars[v];
      if (lifted.local_degree[v] >= 2 || lifted.on_boundary[v] || star.neighbours.size() < 3)
        continue;
      const Eigen::Vector3d start = lifted.sphere[v], start_position = lifted.positions[v];
      const SurfacePoint start_point = lifted.surface_point[v];
      const int start_layer = lifted.layer[v];
      const StarShape before = shape_of(surface, lifted, star);
      Eigen::Vector3d target = relaxed_value(lifted, int(v), star);
      bool kept = false;
      for (int attempt = 0; attempt < 4 && !kept; ++attempt) {
        if ((target - start).norm() < 1e-12) break;
        const std::optional<SurfacePoint> point =
            lift_arc(surface, start_point, start, target, max_steps);
        if (point) {
          lifted.sphere[v] = target;
          lifted.surface_point[v] = *point;
          lifted.positions[v] = position_of(surface, *point);
          if (!face_layer.empty()) lifted.layer[v] = face_layer[point->face];
          kept = better_or_fine(before, shape_of(surface, lifted, star));
        }
        if (!kept) {
          lifted.sphere[v] = start;
          lifted.surface_point[v] = start_point;
          lifted.positions[v] = start_position;
          lifted.layer[v] = start_layer;
          target = (start + target).normalized();
        }
      }
    }
  }
  lifted.folded_lifts = count_folded_lifts(surface, lifted);
}

} // namespace meromorph
