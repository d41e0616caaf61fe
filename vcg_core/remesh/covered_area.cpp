#include "remesh/covered_area.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

#include <Eigen/Geometry>

#include "common/parallel_for.h"

namespace meromorph {
namespace {

// Distance from p to the triangle abc: to its plane where p projects inside, else to the nearest
// side.
double point_triangle_distance(const Eigen::Vector3d &p, const Eigen::Vector3d &a,
                               const Eigen::Vector3d &b, const Eigen::Vector3d &c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double nn = n.squaredNorm();
  if (nn > 0) {
    const double v = (p - a).cross(c - a).dot(n) / nn, w = (b - a).cross(p - a).dot(n) / nn;
    if (v >= 0 && w >= 0 && v + w <= 1) return std::abs((p - a).dot(n)) / std::sqrt(nn);
  }
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto &[x, y] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
    const Eigen::Vector3d e = y - x;
    const double ee = e.squaredNorm();
    const double t = ee > 0 ? std::clamp((p - x).dot(e) / ee, 0.0, 1.0) : 0.0;
    nearest = std::min(nearest, (p - x - t * e).norm());
  }
  return nearest;
}

// The lifted faces' sphere triangles in a grid of cells of every size 2^-level (a triangle in the
// cells of the level whose cell is between half its bounding box and all of it: at most 27), so
// that tiny triangles at a limb's image and large ones elsewhere are both found in a few lookups.
class SphereTriangleGrid {
public:
  SphereTriangleGrid(const LiftedSphere &lifted, const std::vector<int> &faces) : lifted_(lifted) {
    for (int f : faces) {
      const auto &face = lifted.faces[size_t(f)];
      const Eigen::Vector3d &a = lifted.sphere[size_t(face[0])],
                            &b = lifted.sphere[size_t(face[1])],
                            &c = lifted.sphere[size_t(face[2])];
      // The spherical triangle lies within 1 - h of the flat one (h: the plane's distance from
      // the centre).
      const Eigen::Vector3d normal = (b - a).cross(c - a);
      const double norm = normal.norm();
      const double bulge = norm > 0 ? 1.0 - std::abs(normal.dot(a)) / norm : 1.0;
      const Eigen::Vector3d low = a.cwiseMin(b).cwiseMin(c).array() - bulge,
                            high = a.cwiseMax(b).cwiseMax(c).array() + bulge;
      if (!low.allFinite() || !high.allFinite()) continue; // a corner that did not lift
      const double size = std::max((high - low).maxCoeff(), 1e-300);
      const int level = std::clamp(int(std::floor(std::log2(1.0 / size))) + 1, 0, max_level);
      used_[size_t(level)] = true;
      const double cell = std::ldexp(1.0, -level);
      const Cell from = cell_of(low, cell), to = cell_of(high, cell);
      for (long long i = from.x(); i <= to.x(); ++i)
        for (long long j = from.y(); j <= to.y(); ++j)
          for (long long k = from.z(); k <= to.z(); ++k)
            cells_[key(level, {i, j, k})].push_back(f);
    }
  }

  // The lifted face whose sphere triangle holds `image` (of several, the nearest to `position`); -1
  // where none does.
  int face_holding(const Eigen::Vector3d &image, const Eigen::Vector3d &position) const {
    if (!image.allFinite()) return -1;
    int best = -1;
    double nearest = 0;
    for (int level = 0; level <= max_level; ++level) {
      if (!used_[size_t(level)]) continue;
      const auto found = cells_.find(key(level, cell_of(image, std::ldexp(1.0, -level))));
      if (found == cells_.end()) continue;
      for (int f : found->second) {
        if (!holds(f, image)) continue;
        const auto &face = lifted_.faces[size_t(f)];
        const double distance = point_triangle_distance(
            position, lifted_.positions[size_t(face[0])], lifted_.positions[size_t(face[1])],
            lifted_.positions[size_t(face[2])]);
        if (best < 0 || distance < nearest) {
          best = f;
          nearest = distance;
        }
      }
    }
    return best;
  }

private:
  static constexpr int max_level = 50;
  using Cell = Eigen::Matrix<long long, 3, 1>;

  static Cell cell_of(const Eigen::Vector3d &point, double cell) {
    return {(long long)std::floor((point.x() + 2.0) / cell),
            (long long)std::floor((point.y() + 2.0) / cell),
            (long long)std::floor((point.z() + 2.0) / cell)};
  }
  // A cell of a level (counted from a corner of [-2, 2]^3) as one number for the hash map.
  static unsigned long long key(int level, const Cell &cell) {
    unsigned long long h = (unsigned long long)level;
    for (int k = 0; k < 3; ++k)
      h = h * 0x9E3779B97F4A7C15ULL + (unsigned long long)cell[k];
    return h;
  }

  // Inside the cone of the face's sphere triangle, either orientation (a folded lift too).
  bool holds(int f, const Eigen::Vector3d &p) const {
    const auto &face = lifted_.faces[size_t(f)];
    const Eigen::Vector3d &a = lifted_.sphere[size_t(face[0])],
                          &b = lifted_.sphere[size_t(face[1])],
                          &c = lifted_.sphere[size_t(face[2])];
    if (p.dot(a + b + c) <= 0) return false;
    // det(a, b, p) as p . ((a - p) x (b - p)): precise where the triangle is a hair across.
    const Eigen::Vector3d pa = a - p, pb = b - p, pc = c - p;
    const double ab = p.dot(pa.cross(pb)), bc = p.dot(pb.cross(pc)), ca = p.dot(pc.cross(pa));
    return (ab >= 0 && bc >= 0 && ca >= 0) || (ab <= 0 && bc <= 0 && ca <= 0);
  }

  const LiftedSphere &lifted_;
  std::array<bool, max_level + 1> used_{};
  std::unordered_map<unsigned long long, std::vector<int>> cells_;
};

} // namespace

SurfaceSamples sample_surface(const MappedSurface &surface, double largest_sample_area) {
  SurfaceSamples out;
  for (const auto &face : surface.faces) {
    const Eigen::Vector3d &p = surface.positions[size_t(face[0])],
                          &q = surface.positions[size_t(face[1])],
                          &r = surface.positions[size_t(face[2])];
    const double area = 0.5 * (q - p).cross(r - p).norm();
    const int m = std::max(1, int(std::ceil(std::sqrt(area / largest_sample_area))));
    // The centroids of the m x m split: m^2 triangles, upright and upside down.
    for (int i = 0; i < m; ++i)
      for (int j = 0; i + j < m; ++j)
        for (int upside = 0; upside < 2 && i + j + upside < m; ++upside) {
          const double u = (i + (upside ? 2.0 : 1.0) / 3.0) / m,
                       v = (j + (upside ? 2.0 : 1.0) / 3.0) / m;
          const Eigen::Vector3d weights(1.0 - u - v, u, v);
          out.area.push_back(area / (double(m) * m));
          out.position.push_back(weights[0] * p + weights[1] * q + weights[2] * r);
          out.image.push_back((weights[0] * surface.image[size_t(face[0])] +
                               weights[1] * surface.image[size_t(face[1])] +
                               weights[2] * surface.image[size_t(face[2])])
                                  .normalized());
        }
  }
  return out;
}

SampleLocator::SampleLocator(const SurfaceSamples &samples)
    : samples_(&samples), holder_(samples.area.size(), {-1, -1, -1}),
      located_(samples.area.size(), false) {}

std::vector<double> SampleLocator::covered_areas(const LiftedSphere &lifted) {
  std::unordered_map<Corners, int, CornersHash> index;
  index.reserve(lifted.faces.size());
  std::vector<int> fresh; // faces since the last call
  for (size_t f = 0; f < lifted.faces.size(); ++f) {
    index.emplace(lifted.faces[f], int(f));
    if (!known_.count(lifted.faces[f])) fresh.push_back(int(f));
  }
  std::vector<int> holder(samples_->area.size(), -1), moved;
  for (size_t s = 0; s < holder.size(); ++s) {
    if (located_[s] && holder_[s][0] < 0) continue; // held by no face before: not now either
    const auto found = located_[s] ? index.find(holder_[s]) : index.end();
    if (found != index.end())
      holder[s] = found->second;
    else
      moved.push_back(int(s));
  }
  const SphereTriangleGrid grid(lifted, fresh);
  parallel_for(moved.size(), [&](size_t m) {
    const size_t s = size_t(moved[m]);
    holder[s] = grid.face_holding(samples_->image[s], samples_->position[s]);
  });
  std::vector<double> covered(lifted.faces.size(), 0.0);
  for (size_t s = 0; s < holder.size(); ++s) {
    located_[s] = true;
    holder_[s] = holder[s] >= 0 ? lifted.faces[size_t(holder[s])] : Corners{-1, -1, -1};
    if (holder[s] >= 0) covered[size_t(holder[s])] += samples_->area[s];
  }
  known_.clear();
  for (const auto &face : lifted.faces)
    known_.insert(face);
  return covered;
}

} // namespace meromorph
