#include "sphere/texture_coordinates.h"

#include <algorithm>
#include <cmath>

#include "common/parallel_for.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {
namespace {

std::array<double, 2> spherical(const Eigen::Vector3d &p) {
  const double phi = std::atan2(p.y(), p.x());
  const double theta = std::acos(std::clamp(p.z(), -1.0, 1.0));
  return {phi / (2 * M_PI) + 0.5, theta / M_PI};
}

bool at_pole(const Eigen::Vector3d &p) {
  return std::hypot(p.x(), p.y()) < 1e-9;
}

} // namespace

std::array<double, 2> texture_coordinate(const Eigen::Vector3d &p, UvKind kind) {
  if (kind == UvKind::spherical) return spherical(p);
  Complex w = to_plane(p);
  if (std::abs(w) > 1e6) w *= 1e6 / std::abs(w);
  return {w.real(), w.imag()};
}

TextureCoordinates texture_coordinates(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere,
                                       UvKind kind) {
  TextureCoordinates out;
  out.vertex.resize(sphere.size());
  parallel_for(sphere.size(),
               [&](size_t v) { out.vertex[v] = texture_coordinate(sphere[v], kind); });
  out.wedge.resize(mesh.face.size());
  out.around_pole.assign(mesh.face.size(), 0);
  parallel_for(mesh.face.size(), [&](size_t f) {
    int corner_vertex[3];
    for (int k = 0; k < 3; ++k) {
      corner_vertex[k] = index_of(mesh, mesh.face[f].cV(k));
      out.wedge[f][k] = out.vertex[corner_vertex[k]];
    }
    if (kind != UvKind::spherical) return;
    const Eigen::Vector3d &a = sphere[corner_vertex[0]], &b = sphere[corner_vertex[1]],
                          &c = sphere[corner_vertex[2]];
    for (const Eigen::Vector3d &pole : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1)})
      if (a.cross(b).dot(pole) > 0 && b.cross(c).dot(pole) > 0 && c.cross(a).dot(pole) > 0 &&
          pole.dot(a + b + c) > 0)
        out.around_pole[f] = 1;
    auto &w = out.wedge[f];
    // Unwrap across phi = +-pi: lift the corners on the u < 1/2 side by one turn.
    double low = 2, high = -1;
    for (int k = 0; k < 3; ++k)
      if (!at_pole(sphere[corner_vertex[k]])) {
        low = std::min(low, w[k][0]);
        high = std::max(high, w[k][0]);
      }
    if (high - low > 0.5)
      for (int k = 0; k < 3; ++k)
        if (w[k][0] < 0.5) w[k][0] += 1.0;
    // A corner at a pole takes the mean longitude of the others.
    double sum = 0;
    int count = 0;
    for (int k = 0; k < 3; ++k)
      if (!at_pole(sphere[corner_vertex[k]])) {
        sum += w[k][0];
        ++count;
      }
    for (int k = 0; k < 3; ++k)
      if (at_pole(sphere[corner_vertex[k]]) && count) w[k][0] = sum / count;
  });
  return out;
}

} // namespace meromorph
