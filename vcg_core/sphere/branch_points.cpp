#include "sphere/branch_points.h"

#include <algorithm>
#include <cmath>

#include "common/parallel_for.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {

std::vector<double> face_solid_angles(const Mesh &mesh,
                                      const std::vector<Eigen::Vector3d> &sphere) {
  std::vector<double> angles(mesh.face.size());
  parallel_for(mesh.face.size(), [&](size_t f) {
    const MeshFace &face = mesh.face[f];
    angles[f] =
        signed_solid_angle(sphere[index_of(mesh, face.cV(0))], sphere[index_of(mesh, face.cV(1))],
                           sphere[index_of(mesh, face.cV(2))]);
  });
  return angles;
}

double image_area_over_4pi(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere) {
  double total = 0;
  for (double angle : face_solid_angles(mesh, sphere))
    total += angle;
  return total / (4 * M_PI);
}

double corner_sweep(const std::vector<Eigen::Vector3d> &sphere, const std::array<int, 3> &corners,
                    int k, const std::vector<Eigen::Vector3d> &side_midpoints, int face) {
  const Eigen::Vector3d &v = sphere[corners[k]], &a = sphere[corners[(k + 1) % 3]],
                        &b = sphere[corners[(k + 2) % 3]];
  if (side_midpoints.empty()) return swept_angle(v, a, b);
  const Eigen::Vector3d &middle = side_midpoints[3 * size_t(face) + size_t(k)];
  return swept_angle(v, a, middle) + swept_angle(v, middle, b);
}

bool folded_face(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere, int f) {
  const auto &c = in.corners[size_t(f)];
  return folded_image(sphere[size_t(c[0])], sphere[size_t(c[1])], sphere[size_t(c[2])]);
}

bool folded_or_flat(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere, int f) {
  const auto &c = in.corners[f];
  const Eigen::Vector3d &a = sphere[c[0]], &b = sphere[c[1]], &d = sphere[c[2]];
  const double chord =
      std::max({(a - b).squaredNorm(), (b - d).squaredNorm(), (d - a).squaredNorm()});
  if (solid_angle_clearly_above(a, b, d, 1e-9 * chord)) return false; // no arctangent needed
  return !(signed_solid_angle(a, b, d) > 1e-9 * chord);
}

int vertex_winding(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere, int v,
                   const std::vector<Eigen::Vector3d> &side_midpoints) {
  double total = 0;
  for (int f : in.faces_of_vertex[v]) {
    const auto &c = in.corners[f];
    const int k = int(std::find(c.begin(), c.end(), v) - c.begin());
    total += corner_sweep(sphere, c, k, side_midpoints, f);
  }
  return int(std::lround(total / (2 * M_PI)));
}

Branching analyse_branching(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere, int euler,
                            const std::vector<Eigen::Vector3d> &side_midpoints) {
  Branching out;
  // Winding: each face (v, a, b) adds the angle from a to b around v's image. The angles are
  // measured over the cores and summed per vertex in face order.
  std::vector<std::array<double, 3>> sweeps(mesh.face.size());
  parallel_for(mesh.face.size(), [&](size_t f) {
    const MeshFace &face = mesh.face[f];
    const std::array<int, 3> corners{index_of(mesh, face.cV(0)), index_of(mesh, face.cV(1)),
                                     index_of(mesh, face.cV(2))};
    for (int k = 0; k < 3; ++k)
      sweeps[f][size_t(k)] = corner_sweep(sphere, corners, k, side_midpoints, int(f));
  });
  std::vector<double> winding(mesh.vert.size(), 0.0);
  for (size_t f = 0; f < mesh.face.size(); ++f)
    for (int k = 0; k < 3; ++k)
      winding[size_t(index_of(mesh, mesh.face[f].cV(k)))] += sweeps[f][size_t(k)];
  out.local_degree.resize(mesh.vert.size());
  for (size_t v = 0; v < mesh.vert.size(); ++v) {
    const int e = int(std::lround(winding[v] / (2 * M_PI)));
    out.local_degree[v] = e;
    if (e >= 2) out.branch_vertices.push_back(int(v));
    out.ramification += e - 1;
  }
  out.area_over_4pi = image_area_over_4pi(mesh, sphere);
  out.degree = int(std::lround(out.area_over_4pi));
  out.riemann_hurwitz_ok =
      euler == 2 * out.degree - out.ramification && std::abs(out.area_over_4pi - out.degree) < 0.01;
  return out;
}

} // namespace meromorph
