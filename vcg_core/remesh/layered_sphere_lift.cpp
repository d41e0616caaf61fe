#include "remesh/layered_sphere_lift.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include <Eigen/Geometry>

#include "common/errors.h"

namespace meromorph {
namespace {

struct Lift {
  SurfacePoint point;
  Eigen::Vector3d position;
};

// The lifts of every sphere vertex, and for every directed sphere edge from a vertex that carries
// no branch value and each lift of its start, which lift of its end the edge's lift reaches.
class EdgeLifting {
public:
  EdgeLifting(const MappedSurface &surface, const GeodesicSphere &sphere, int degree)
      : surface_(surface), sphere_(sphere), degree_(degree), lifts_(sphere.vertices.size()) {
    first_edge_.push_back(0);
    for (const auto &around : sphere.neighbours)
      first_edge_.push_back(first_edge_.back() + int(around.size()));
    reached_.assign(size_t(first_edge_.back()) * degree, -1);
    double extent = 0;
    for (const Eigen::Vector3d &p : surface.positions)
      extent = std::max(extent, p.cwiseAbs().maxCoeff());
    same_point_ = 1e-7 * std::max(extent, 1e-300);
    max_steps_ = int(surface.faces.size()) + 16;
  }

  void run(const Progress &progress) {
    std::deque<int> queue{seed()};
    std::vector<char> queued(sphere_.vertices.size(), 0);
    queued[queue.front()] = 1;
    size_t done = 0;
    while (!queue.empty()) {
      const int q = queue.front();
      queue.pop_front();
      walk_edges_from(q);
      for (int r : sphere_.neighbours[q])
        if (!queued[r] && sphere_.branch_value[r] < 0 && !lifts_[r].empty()) {
          queued[r] = 1;
          queue.push_back(r);
        }
      if (++done % 4096 == 0)
        progress.report(double(done) / double(sphere_.vertices.size()), "lifting the sphere");
    }
  }

  const std::vector<Lift> &lifts(int q) const { return lifts_[q]; }
  // The lift of r reached from lift i of q along edge q -> r, or -1.
  int reached(int q, int r, int i) const {
    const auto &around = sphere_.neighbours[q];
    for (size_t n = 0; n < around.size(); ++n)
      if (around[n] == r) return reached_[(size_t(first_edge_[q]) + n) * degree_ + i];
    return -1;
  }

private:
  // A vertex carrying no branch value over which exactly d points are found.
  int seed() {
    const int count = int(sphere_.vertices.size());
    for (int attempt = 0; attempt < 64; ++attempt) {
      const int q = int((long long)(attempt)*7919 % count);
      if (sphere_.branch_value[q] >= 0) continue;
      const std::vector<SurfacePoint> over = points_over(surface_, sphere_.vertices[q]);
      if (int(over.size()) != degree_) continue;
      for (const SurfacePoint &point : over)
        lifts_[q].push_back({point, position_of(surface_, point)});
      return q;
    }
    throw InternalError("remesh: no point of the sphere was found covered exactly " +
                        std::to_string(degree_) + " times by the map");
  }

  int match(int r, SurfacePoint point) {
    if (sphere_.branch_value[r] >= 0) point = at_corner_over(point, sphere_.vertices[r]);
    const Eigen::Vector3d p = position_of(surface_, point);
    auto &known = lifts_[r];
    for (size_t j = 0; j < known.size(); ++j)
      if ((known[j].position - p).norm() < same_point_) return int(j);
    known.push_back({point, p});
    return int(known.size()) - 1;
  }

  void walk_edges_from(int q) {
    const auto &around = sphere_.neighbours[q];
    const int lifts = std::min<int>(int(lifts_[q].size()), degree_);
    for (size_t n = 0; n < around.size(); ++n) {
      const int r = around[n];
      for (int i = 0; i < lifts; ++i) {
        const std::optional<SurfacePoint> end = lift_arc(
            surface_, lifts_[q][i].point, sphere_.vertices[q], sphere_.vertices[r], max_steps_);
        if (end) reached_[(size_t(first_edge_[q]) + n) * degree_ + i] = match(r, *end);
      }
    }
  }

  // A walk that ends over a branch value ends at the corner of its face (or of a face one or two
  // sides away) whose image that value is (within its face the map takes the value nowhere else).
  // Near a branch point the surface position moves as the square root of the value, so an end a
  // rounding away from the corner would lie farther from it than lifts are matched by (seen on two
  // branch points of one pair of sheets 1.6e-4 apart on the sphere: the branch point found three
  // times).
  SurfacePoint at_corner_over(const SurfacePoint &point, const Eigen::Vector3d &value) const {
    // The face itself, then the faces across its sides and theirs (a walk may stop a rounding
    // short, in a face next to the branch vertex's own where the image is tiny).
    std::vector<int> faces{point.face};
    for (size_t next = 0; next < faces.size() && faces.size() < 16; ++next) {
      const int f = faces[next];
      for (int k = 0; k < 3; ++k)
        if ((surface_.image[size_t(surface_.faces[size_t(f)][k])] - value).norm() < 1e-12) {
          SurfacePoint corner{f, Eigen::Vector3d::Zero()};
          corner.weights[k] = 1;
          return corner;
        }
      if (next < 4)
        for (int across : surface_.across[size_t(f)])
          if (across >= 0 && std::find(faces.begin(), faces.end(), across) == faces.end())
            faces.push_back(across);
    }
    return point;
  }

  const MappedSurface &surface_;
  const GeodesicSphere &sphere_;
  int degree_;
  std::vector<std::vector<Lift>> lifts_;
  std::vector<int> first_edge_, reached_;
  double same_point_ = 0;
  int max_steps_ = 0;
};

Eigen::Vector3d surface_normal_at(const MappedSurface &surface, const SurfacePoint &point) {
  const auto &c = surface.faces[point.face];
  const Eigen::Vector3d &a = surface.positions[c[0]], &b = surface.positions[c[1]],
                        &d = surface.positions[c[2]];
  const Eigen::Vector3d normal = (b - a).cross(d - a);
  const double norm = normal.norm();
  return norm > 0 ? Eigen::Vector3d(normal / norm) : Eigen::Vector3d::Zero();
}

int local_degree_at(const MappedSurface &surface, const SurfacePoint &point,
                    const std::vector<int> &local_degree) {
  for (int k = 0; k < 3; ++k)
    if (point.weights[k] > 1 - 1e-9) {
      const int e = local_degree[surface.faces[point.face][k]];
      return e >= 2 ? e : 0;
    }
  return 0;
}

} // namespace

bool lifted_face_folds(const MappedSurface &surface, const LiftedSphere &lifted,
                       const std::array<int, 3> &face) {
  const Eigen::Vector3d &p = lifted.positions[face[0]], &q = lifted.positions[face[1]],
                        &r = lifted.positions[face[2]];
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  for (int corner : face)
    reference += surface_normal_at(surface, lifted.surface_point[corner]);
  return (q - p).cross(r - p).dot(reference) < 0;
}

double corner_angle(const Eigen::Vector3d &at, const Eigen::Vector3d &to,
                    const Eigen::Vector3d &from) {
  const Eigen::Vector3d u = to - at, v = from - at;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

double smallest_corner_angle(const LiftedSphere &lifted, const std::array<int, 3> &face) {
  double smallest = M_PI;
  for (int k = 0; k < 3; ++k)
    smallest = std::min(smallest,
                        corner_angle(lifted.positions[face[k]], lifted.positions[face[(k + 1) % 3]],
                                     lifted.positions[face[(k + 2) % 3]]));
  return smallest;
}

bool positive_on_sphere(const LiftedSphere &lifted, const std::array<int, 3> &face) {
  return lifted.sphere[face[0]].dot(lifted.sphere[face[1]].cross(lifted.sphere[face[2]])) > 0;
}

int count_folded_lifts(const MappedSurface &surface, const LiftedSphere &lifted) {
  int folded = 0;
  for (const auto &face : lifted.faces)
    folded += lifted_face_folds(surface, lifted, face);
  return folded;
}

LiftedSphere lift_sphere(const MappedSurface &surface, const std::vector<int> &face_layer,
                         const std::vector<int> &local_degree, int degree,
                         const GeodesicSphere &sphere, const Progress &progress) {
  EdgeLifting lifting(surface, sphere, degree);
  lifting.run(progress.range(0.0, 0.9));

  LiftedSphere out;
  std::vector<int> first(sphere.vertices.size() + 1, 0);
  for (size_t q = 0; q < sphere.vertices.size(); ++q) {
    first[q + 1] = first[q] + int(lifting.lifts(int(q)).size());
    for (const Lift &lift : lifting.lifts(int(q))) {
      out.positions.push_back(lift.position);
      out.sphere.push_back(sphere.vertices[q]);
      out.layer.push_back(face_layer.empty() ? 0 : face_layer[lift.point.face]);
      out.local_degree.push_back(local_degree_at(surface, lift.point, local_degree));
      out.surface_point.push_back(lift.point);
    }
  }
  progress.report(0.9, "joining the lifted faces");
  for (const auto &face : sphere.faces) {
    int base = 0; // a corner that carries no branch value starts the lifts
    while (base < 3 && sphere.branch_value[face[base]] >= 0)
      ++base;
    if (base == 3 || lifting.lifts(face[base]).empty()) {
      out.unlifted_faces += degree;
      continue;
    }
    const int a = face[base], b = face[(base + 1) % 3], c = face[(base + 2) % 3];
    const int lifts = std::min<int>(int(lifting.lifts(a).size()), degree);
    out.unlifted_faces += degree - lifts;
    for (int i = 0; i < lifts; ++i) {
      const int j = lifting.reached(a, b, i), k = lifting.reached(a, c, i);
      if (j < 0 || k < 0) {
        ++out.unlifted_faces;
        continue;
      }
      if (sphere.branch_value[b] < 0 && lifting.reached(b, c, j) != k) {
        ++out.unclosed_faces;
        continue;
      }
      std::array<int, 3> lifted{first[a] + i, first[b] + j, first[c] + k};
      std::array<int, 3> rotated{};
      for (int m = 0; m < 3; ++m)
        rotated[(base + m) % 3] = lifted[m];
      out.faces.push_back(rotated);
    }
  }
  out.folded_lifts = count_folded_lifts(surface, out);
  progress.report(1.0, "lifted");
  return out;
}

} // namespace meromorph
