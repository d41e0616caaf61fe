#include "maps/added_vertices.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace meromorph {

std::vector<std::array<int, 2>> sides_to_cut(const Mesh &mesh, const Parameterization &map) {
  std::set<std::array<int, 2>> sides;
  auto cut = [&](const MeshFace &face, int side) { // from corner side to corner side + 1
    const int u = index_of(mesh, face.cV(side)), v = index_of(mesh, face.cV((side + 1) % 3));
    sides.insert({std::min(u, v), std::max(u, v)});
  };
  // Corners the map opens to half a turn or more at branch points.
  for (const MeshFace &face : mesh.face)
    for (int k = 0; k < 3; ++k) {
      const int e = map.branch_flag[size_t(index_of(mesh, face.cV(k)))];
      if (e >= 2 &&
          vcg::Angle(face.cP((k + 1) % 3) - face.cP(k), face.cP((k + 2) % 3) - face.cP(k)) * e >=
              0.98 * M_PI)
        cut(face, (k + 1) % 3);
    }
  for (int f : map.quality.folded_face_indices) {
    const MeshFace &face = mesh.face[size_t(f)];
    int side = 0;
    double length = -1;
    for (int k = 0; k < 3; ++k) {
      const int opposite = index_of(mesh, face.cV((k + 2) % 3));
      const bool faces_branch = map.branch_flag[size_t(opposite)] >= 2;
      const double l = (face.cP(k) - face.cP((k + 1) % 3)).Norm() + (faces_branch ? 1e300 : 0);
      if (l > length) length = l, side = k;
    }
    cut(face, side);
  }
  return {sides.begin(), sides.end()};
}

std::vector<AddedVertex> places_on(const Mesh &mesh, const std::vector<Point3> &positions,
                                   const MeshArrays &cut, const std::vector<int> &face_source) {
  const size_t own = mesh.vert.size();
  std::vector<AddedVertex> added(cut.positions.size() - own);
  std::vector<char> placed(added.size(), 0);
  for (size_t t = 0; t < cut.triangles.size(); ++t)
    for (int v : cut.triangles[t]) {
      if (size_t(v) < own || placed[size_t(v) - own]) continue;
      placed[size_t(v) - own] = 1;
      const int f = face_source[t];
      const MeshFace &face = mesh.face[size_t(f)];
      const Point3 e1 = face.cP(1) - face.cP(0), e2 = face.cP(2) - face.cP(0),
                   d = cut.positions[size_t(v)] - face.cP(0);
      const double g11 = e1.dot(e1), g12 = e1.dot(e2), g22 = e2.dot(e2);
      const double det = g11 * g22 - g12 * g12;
      const double b1 = det > 0 ? (g22 * d.dot(e1) - g12 * d.dot(e2)) / det : 0;
      const double b2 = det > 0 ? (g11 * d.dot(e2) - g12 * d.dot(e1)) / det : 0;
      auto at = [&](int k) { return positions[size_t(index_of(mesh, face.cV(k)))]; };
      const Point3 p = at(0) * (1 - b1 - b2) + at(1) * b1 + at(2) * b2;
      added[size_t(v) - own] = {f, b1, b2, Eigen::Vector3d(p[0], p[1], p[2])};
    }
  return added;
}

} // namespace meromorph
