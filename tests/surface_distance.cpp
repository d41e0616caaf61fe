#include "surface_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace meromorph::test {
namespace {

Vec3 along(const Vec3 &a, const Vec3 &d, double t) {
  return {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]};
}

// Distance from p to triangle abc: the projection when it falls inside, else the nearest side.
double point_triangle(const Vec3 &p, const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  const Vec3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a), n = cross(ab, ac);
  const double nn = dot(n, n);
  if (nn > 0) {
    const double v = dot(cross(ap, ac), n) / nn, w = dot(cross(ab, ap), n) / nn;
    if (v >= 0 && w >= 0 && v + w <= 1) return std::abs(dot(ap, n)) / std::sqrt(nn);
  }
  double best = std::numeric_limits<double>::infinity();
  for (const auto &[x, y] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
    const Vec3 e = sub(y, x);
    const double ee = dot(e, e);
    const double t = ee > 0 ? std::clamp(dot(sub(p, x), e) / ee, 0.0, 1.0) : 0.0;
    best = std::min(best, norm(sub(p, along(x, e, t))));
  }
  return best;
}

} // namespace

NearestOnSurface::NearestOnSurface(const std::vector<Vec3> &positions,
                                   const std::vector<std::array<int, 3>> &triangles)
    : positions_(positions), triangles_(triangles) {
  Vec3 high{};
  low_ = high = positions.front();
  for (const Vec3 &p : positions)
    for (int k = 0; k < 3; ++k) {
      low_[k] = std::min(low_[k], p[k]);
      high[k] = std::max(high[k], p[k]);
    }
  diagonal_ = norm(sub(high, low_));
  cell_ = diagonal_ / std::cbrt(double(triangles.size()) + 1) + 1e-300;
  for (int k = 0; k < 3; ++k)
    cells_[k] = (long long)std::floor((high[k] - low_[k]) / cell_) + 1;
  for (size_t t = 0; t < triangles.size(); ++t) {
    std::array<long long, 3> from{}, to{};
    for (int k = 0; k < 3; ++k) {
      double lo = positions[triangles[t][0]][k], hi = lo;
      for (int corner : triangles[t]) {
        lo = std::min(lo, positions[corner][k]);
        hi = std::max(hi, positions[corner][k]);
      }
      from[k] = (long long)std::floor((lo - low_[k]) / cell_);
      to[k] = (long long)std::floor((hi - low_[k]) / cell_);
    }
    for (long long i = from[0]; i <= to[0]; ++i)
      for (long long j = from[1]; j <= to[1]; ++j)
        for (long long k = from[2]; k <= to[2]; ++k)
          grid_[cell_key(i, j, k)].push_back(int(t));
  }
}

long long NearestOnSurface::cell_key(long long i, long long j, long long k) const {
  return (i * (cells_[1] + 2) + j) * (cells_[2] + 2) + k;
}

NearestOnSurface::Nearest NearestOnSurface::operator()(const Vec3 &point) const {
  std::array<long long, 3> home{};
  for (int k = 0; k < 3; ++k)
    home[k] = std::clamp((long long)std::floor((point[k] - low_[k]) / cell_), 0LL, cells_[k] - 1);
  Nearest best;
  best.distance = std::numeric_limits<double>::infinity();
  int best_triangle = -1;
  const long long most = std::max({cells_[0], cells_[1], cells_[2]});
  for (long long ring = 0; ring <= most; ++ring) {
    // Every triangle within `ring` cells has been seen: nothing nearer than ring * cell is left.
    if (best_triangle >= 0 && best.distance < double(ring - 1) * cell_) break;
    for (long long i = home[0] - ring; i <= home[0] + ring; ++i)
      for (long long j = home[1] - ring; j <= home[1] + ring; ++j)
        for (long long k = home[2] - ring; k <= home[2] + ring; ++k) {
          if (std::max({std::abs(i - home[0]), std::abs(j - home[1]), std::abs(k - home[2])}) !=
              ring)
            continue;
          if (i < 0 || j < 0 || k < 0 || i >= cells_[0] || j >= cells_[1] || k >= cells_[2])
            continue;
          const auto found = grid_.find(cell_key(i, j, k));
          if (found == grid_.end()) continue;
          for (int t : found->second) {
            const auto &c = triangles_[t];
            const double d =
                point_triangle(point, positions_[c[0]], positions_[c[1]], positions_[c[2]]);
            if (d < best.distance) {
              best.distance = d;
              best_triangle = t;
            }
          }
        }
  }
  if (best_triangle >= 0) {
    const auto &c = triangles_[best_triangle];
    const Vec3 n =
        cross(sub(positions_[c[1]], positions_[c[0]]), sub(positions_[c[2]], positions_[c[0]]));
    const double length = norm(n);
    if (length > 0) best.normal = {n[0] / length, n[1] / length, n[2] / length};
  }
  return best;
}

} // namespace meromorph::test
