#include "remesh/covered_area.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

#include <Eigen/Geometry>

#include "common/parallel_for.h"
#include "sphere/sphere_triangle_grid.h"

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

// The face whose sphere triangle holds `image` (of several lifted copies, the one whose lifted
// triangle lies nearest `position`: the sheet the sample is on); -1 where none does.
int face_holding(const SphereTriangleGrid &grid, const LiftedSphere &lifted,
                 const Eigen::Vector3d &image, const Eigen::Vector3d &position) {
  int best = -1;
  double nearest = 0;
  grid.for_each_holding(image, [&](int f) {
    const auto &face = lifted.faces[size_t(f)];
    const double distance = point_triangle_distance(position, lifted.positions[size_t(face[0])],
                                                    lifted.positions[size_t(face[1])],
                                                    lifted.positions[size_t(face[2])]);
    if (best < 0 || distance < nearest) {
      best = f;
      nearest = distance;
    }
  });
  return best;
}

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
  const SphereTriangleGrid grid(lifted.sphere, lifted.faces, fresh);
  parallel_for(moved.size(), [&](size_t m) {
    const size_t s = size_t(moved[m]);
    holder[s] = face_holding(grid, lifted, samples_->image[s], samples_->position[s]);
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
