#include "maps/floater_embedding.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace meromorph {
namespace {

// tan of half the angle at corner i of `face`, on the surface.
double tan_half_angle(const Mesh &mesh, const std::array<int, 3> &face, int i) {
  const Point3 &p = mesh.vert[size_t(face[size_t(i)])].cP(),
               &q = mesh.vert[size_t(face[size_t((i + 1) % 3)])].cP(),
               &r = mesh.vert[size_t(face[size_t((i + 2) % 3)])].cP();
  const Point3 a = q - p, b = r - p;
  return std::tan(std::atan2((a ^ b).Norm(), a * b) / 2);
}

} // namespace

bool floater_embedding(const Mesh &mesh, const FaceIncidence &incidence,
                       const std::vector<int> &free, std::map<int, Eigen::Vector2d> &chart) {
  std::map<int, std::map<int, double>> weight;
  for (int v : free)
    for (int g : incidence.faces_of_vertex[size_t(v)]) {
      const auto &t = incidence.corners[size_t(g)];
      const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
      const int ahead = t[size_t((k + 1) % 3)], behind = t[size_t((k + 2) % 3)];
      const double w = tan_half_angle(mesh, t, k);
      const double to_ahead = (mesh.vert[size_t(v)].cP() - mesh.vert[size_t(ahead)].cP()).Norm(),
                   to_behind = (mesh.vert[size_t(v)].cP() - mesh.vert[size_t(behind)].cP()).Norm();
      if (!(to_ahead > 0 && to_behind > 0 && std::isfinite(w))) return false;
      weight[v][ahead] += w / to_ahead;
      weight[v][behind] += w / to_behind;
    }
  for (int sweep = 0; sweep < 1000; ++sweep) {
    double change = 0;
    for (auto &[v, neighbours] : weight) {
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      double total = 0;
      for (const auto &[w, value] : neighbours) {
        sum += value * chart[w];
        total += value;
      }
      const Eigen::Vector2d moved = sum / total;
      change = std::max(change, (moved - chart[v]).norm());
      chart[v] = moved;
    }
    if (change < 1e-15) break;
  }
  return true;
}

GnomonicChart::GnomonicChart(const Eigen::Vector3d &centre_)
    : centre(centre_.normalized()), u1(centre.unitOrthogonal()), u2(centre.cross(u1)) {}

bool GnomonicChart::to_chart(const Eigen::Vector3d &p, Eigen::Vector2d &x) const {
  const double height = p.dot(centre);
  if (!(height > 0.1)) return false;
  x = {p.dot(u1) / height, p.dot(u2) / height};
  return true;
}

Eigen::Vector3d GnomonicChart::to_sphere(const Eigen::Vector2d &x) const {
  return (centre + x.x() * u1 + x.y() * u2).normalized();
}

} // namespace meromorph
