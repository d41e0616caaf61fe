#include "sphere/map_quality.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "common/parallel_for.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {
namespace {

struct FaceMeasure {
  double quasi_conformal;
  double angle_error_degrees;
  bool folded;
  bool collapsed;
};

// Triangle corners in a 2D frame of its own plane.
Eigen::Matrix2d frame_edges(const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                            const Eigen::Vector3d &c) {
  const Eigen::Vector3d e1 = (b - a).normalized();
  const Eigen::Vector3d normal = (b - a).cross(c - a);
  const Eigen::Vector3d e2 = normal.normalized().cross(e1);
  Eigen::Matrix2d edges;
  edges << (b - a).dot(e1), (c - a).dot(e1), (b - a).dot(e2), (c - a).dot(e2);
  return edges;
}

// The singular values of a 2 x 2 matrix, largest first, in closed form: M = (E + F, G + H; ...)
// splits into a similarity (E, H) and an anti-similarity (F, G); the values are the sum and the
// difference of their scales.
std::array<double, 2> singular_values(const Eigen::Matrix2d &m) {
  const double e = (m(0, 0) + m(1, 1)) / 2, f = (m(0, 0) - m(1, 1)) / 2;
  const double g = (m(1, 0) + m(0, 1)) / 2, h = (m(1, 0) - m(0, 1)) / 2;
  const double q = std::hypot(e, h), r = std::hypot(f, g);
  return {q + r, std::abs(q - r)};
}

double angle(const Eigen::Vector3d &at, const Eigen::Vector3d &p, const Eigen::Vector3d &q) {
  const Eigen::Vector3d u = p - at, v = q - at;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

QualityStatistics summarize(std::vector<FaceMeasure> measures) {
  QualityStatistics s;
  s.faces = int(measures.size());
  if (measures.empty()) return s;
  std::vector<double> ratios;
  ratios.reserve(measures.size());
  for (const FaceMeasure &m : measures) {
    ratios.push_back(m.quasi_conformal);
    s.quasi_conformal_mean += m.quasi_conformal;
    s.angle_error_mean_degrees += m.angle_error_degrees;
    s.folded_faces += m.folded;
    s.collapsed_faces += m.collapsed;
  }
  s.quasi_conformal_mean /= double(measures.size());
  s.angle_error_mean_degrees /= double(measures.size());
  s.quasi_conformal_max = *std::max_element(ratios.begin(), ratios.end());
  const auto p95 = ratios.begin() + long(0.95 * double(ratios.size() - 1));
  std::nth_element(ratios.begin(), p95, ratios.end());
  s.quasi_conformal_p95 = *p95;
  return s;
}

} // namespace

std::array<double, 3> face_corner_angles(const Mesh &mesh, int face) {
  Eigen::Vector3d p[3];
  for (int k = 0; k < 3; ++k)
    p[k] = mesh.face[face].cP(k).ToEigenVector<Eigen::Vector3d>();
  std::array<double, 3> angles;
  for (int k = 0; k < 3; ++k)
    angles[size_t(k)] = angle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
  return angles;
}

double face_angle_error_degrees(const std::array<double, 3> &corner_angles, const Mesh &mesh,
                                const std::vector<Eigen::Vector3d> &sphere, int face) {
  Eigen::Vector3d s[3];
  for (int k = 0; k < 3; ++k)
    s[k] = sphere[index_of(mesh, mesh.face[face].cV(k))];
  double error = 0;
  for (int k = 0; k < 3; ++k)
    error += std::abs(corner_angles[size_t(k)] - angle(s[k], s[(k + 1) % 3], s[(k + 2) % 3]));
  return error * 180.0 / M_PI / 3.0;
}

double face_angle_error_degrees(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere,
                                int face) {
  return face_angle_error_degrees(face_corner_angles(mesh, face), mesh, sphere, face);
}

bool folded_as_measured(const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                        const Eigen::Vector3d &c) {
  // Folded also when the chord triangle is not clearly positively oriented (by 1e-12 of its
  // longest side squared), so that no reader of the written positions can see it turned over
  // (flat images at branch points), unless it shrinks below what doubles resolve.
  return folded_image(a, b, c) || (chord_turned_over(a, b, c, 1e-12) && !collapsed_image(a, b, c));
}

double mean_angle_error_degrees(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere) {
  const double sum = chunked_sum(mesh.face.size(), 0.0, [&](size_t begin, size_t end) {
    double part = 0;
    for (size_t f = begin; f < end; ++f)
      part += face_angle_error_degrees(mesh, sphere, int(f));
    return part;
  });
  return mesh.face.empty() ? 0.0 : sum / double(mesh.face.size());
}

MapQuality measure_map_quality(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere,
                               const std::vector<int> &branch_vertices) {
  std::vector<char> near_branch(mesh.vert.size(), 0);
  for (int v : branch_vertices)
    near_branch[v] = 1;
  std::vector<FaceMeasure> all(mesh.face.size()), away;
  std::vector<char> touches_branch(mesh.face.size(), 0);
  std::vector<int> folded, collapsed;
  parallel_for(mesh.face.size(), [&](size_t f) {
    const MeshFace &face = mesh.face[f];
    Eigen::Vector3d p[3], s[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = face.cP(k).ToEigenVector<Eigen::Vector3d>();
      const int v = index_of(mesh, face.cV(k));
      s[k] = sphere[v];
      touches_branch[f] |= near_branch[v];
    }
    FaceMeasure m{1.0, 0.0, folded_as_measured(s[0], s[1], s[2]),
                  collapsed_image(s[0], s[1], s[2])};
    const Eigen::Matrix2d source = frame_edges(p[0], p[1], p[2]);
    const Eigen::Matrix2d image = frame_edges(s[0], s[1], s[2]);
    const std::array<double, 2> stretch = singular_values(image * source.inverse());
    m.quasi_conformal = stretch[1] > 0 ? stretch[0] / stretch[1] : 1e300;
    if (!std::isfinite(m.quasi_conformal)) m.quasi_conformal = 1e300;
    m.angle_error_degrees = face_angle_error_degrees(mesh, sphere, int(f));
    all[f] = m;
  });
  away.reserve(all.size());
  for (size_t f = 0; f < all.size(); ++f) {
    if (all[f].folded) folded.push_back(int(f));
    if (all[f].collapsed) collapsed.push_back(int(f));
    if (!touches_branch[f]) away.push_back(all[f]);
  }
  return {summarize(all), summarize(away), std::move(folded), std::move(collapsed)};
}

} // namespace meromorph
