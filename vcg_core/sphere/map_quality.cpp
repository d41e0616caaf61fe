#include "sphere/map_quality.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

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

double angle(const Eigen::Vector3d &at, const Eigen::Vector3d &p, const Eigen::Vector3d &q) {
  const Eigen::Vector3d u = p - at, v = q - at;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

QualityStatistics summarize(std::vector<FaceMeasure> measures) {
  QualityStatistics s;
  s.faces = int(measures.size());
  if (measures.empty()) return s;
  std::vector<double> ratios;
  for (const FaceMeasure &m : measures) {
    ratios.push_back(m.quasi_conformal);
    s.quasi_conformal_mean += m.quasi_conformal;
    s.angle_error_mean_degrees += m.angle_error_degrees;
    s.folded_faces += m.folded;
    s.collapsed_faces += m.collapsed;
  }
  s.quasi_conformal_mean /= double(measures.size());
  s.angle_error_mean_degrees /= double(measures.size());
  std::sort(ratios.begin(), ratios.end());
  s.quasi_conformal_p95 = ratios[size_t(0.95 * double(ratios.size() - 1))];
  s.quasi_conformal_max = ratios.back();
  return s;
}

} // namespace

double face_angle_error_degrees(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere,
                                int face) {
  Eigen::Vector3d p[3], s[3];
  for (int k = 0; k < 3; ++k) {
    p[k] = mesh.face[face].cP(k).ToEigenVector<Eigen::Vector3d>();
    s[k] = sphere[index_of(mesh, mesh.face[face].cV(k))];
  }
  double error = 0;
  for (int k = 0; k < 3; ++k)
    error += std::abs(angle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]) -
                      angle(s[k], s[(k + 1) % 3], s[(k + 2) % 3]));
  return error * 180.0 / M_PI / 3.0;
}

MapQuality measure_map_quality(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere,
                               const std::vector<int> &branch_vertices) {
  std::vector<char> near_branch(mesh.vert.size(), 0);
  for (int v : branch_vertices)
    near_branch[v] = 1;
  std::vector<FaceMeasure> all, away;
  std::vector<int> folded, collapsed;
  all.reserve(mesh.face.size());
  for (size_t f = 0; f < mesh.face.size(); ++f) {
    const MeshFace &face = mesh.face[f];
    Eigen::Vector3d p[3], s[3];
    bool touches_branch = false;
    for (int k = 0; k < 3; ++k) {
      p[k] = face.cP(k).ToEigenVector<Eigen::Vector3d>();
      const int v = index_of(mesh, face.cV(k));
      s[k] = sphere[v];
      touches_branch |= near_branch[v] != 0;
    }
    FaceMeasure m{1.0, 0.0, folded_image(s[0], s[1], s[2]), collapsed_image(s[0], s[1], s[2])};
    const Eigen::Matrix2d source = frame_edges(p[0], p[1], p[2]);
    const Eigen::Matrix2d image = frame_edges(s[0], s[1], s[2]);
    const Eigen::JacobiSVD<Eigen::Matrix2d> svd(image * source.inverse());
    const double smallest = svd.singularValues()[1];
    m.quasi_conformal =
        smallest > 0 ? svd.singularValues()[0] / smallest : std::numeric_limits<double>::infinity();
    if (!std::isfinite(m.quasi_conformal)) m.quasi_conformal = 1e300;
    m.angle_error_degrees = face_angle_error_degrees(mesh, sphere, int(f));
    if (m.folded) folded.push_back(int(f));
    if (m.collapsed) collapsed.push_back(int(f));
    all.push_back(m);
    if (!touches_branch) away.push_back(m);
  }
  return {summarize(all), summarize(away), std::move(folded), std::move(collapsed)};
}

} // namespace meromorph
