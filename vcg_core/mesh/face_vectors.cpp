#include "mesh/face_vectors.h"

#include <algorithm>
#include <cmath>

namespace meromorph {
FaceGeometry face_geometry(const Mesh &mesh) {
  FaceGeometry geometry;
  geometry.normals.reserve(mesh.face.size());
  geometry.areas.reserve(mesh.face.size());
  for (const MeshFace &face : mesh.face) {
    const Eigen::Vector3d p0 = face.cP(0).ToEigenVector<Eigen::Vector3d>(),
                          p1 = face.cP(1).ToEigenVector<Eigen::Vector3d>(),
                          p2 = face.cP(2).ToEigenVector<Eigen::Vector3d>();
    const Eigen::Vector3d cross = (p1 - p0).cross(p2 - p0);
    geometry.areas.push_back(0.5 * cross.norm());
    geometry.normals.push_back(cross.normalized());
  }
  return geometry;
}

double corner_angle(const MeshFace &face, int k) {
  const Point3 u = face.cP((k + 1) % 3) - face.cP(k), w = face.cP((k + 2) % 3) - face.cP(k);
  return std::atan2((u ^ w).Norm(), u * w);
}

double smallest_angle(const MeshFace &face) {
  return std::min({corner_angle(face, 0), corner_angle(face, 1), corner_angle(face, 2)});
}

std::vector<double> vertex_areas(const Mesh &mesh) {
  return vertex_areas(mesh, face_geometry(mesh));
}

std::vector<double> vertex_areas(const Mesh &mesh, const FaceGeometry &geometry) {
  std::vector<double> areas(mesh.vert.size(), 0.0);
  for (size_t f = 0; f < mesh.face.size(); ++f)
    for (int k = 0; k < 3; ++k)
      areas[index_of(mesh, mesh.face[f].cV(k))] += geometry.areas[f] / 3;
  return areas;
}

Eigen::MatrixX3d face_vectors(const Mesh &mesh, const MeshEdges &edges,
                              const FaceGeometry &geometry, const Eigen::VectorXd &form) {
  Eigen::MatrixX3d vectors(mesh.face.size(), 3);
  for (size_t f = 0; f < mesh.face.size(); ++f) {
    const MeshFace &face = mesh.face[f];
    const Eigen::Vector3d p0 = face.cP(0).ToEigenVector<Eigen::Vector3d>(),
                          p1 = face.cP(1).ToEigenVector<Eigen::Vector3d>(),
                          p2 = face.cP(2).ToEigenVector<Eigen::Vector3d>();
    // Local potential: u0 = 0, u1 = form along side 0, u2 = u1 + form along side 1.
    const double u1 = edges.face_signs[f][0] * form[edges.face_edges[f][0]];
    const double u2 = u1 + edges.face_signs[f][1] * form[edges.face_edges[f][1]];
    const Eigen::Vector3d &n = geometry.normals[f];
    // grad phi_i = n x (edge opposite corner i, counter-clockwise) / (2 area).
    vectors.row(long(f)) =
        (u1 * n.cross(p0 - p2) + u2 * n.cross(p1 - p0)) / (2.0 * geometry.areas[f]);
  }
  return vectors;
}

} // namespace meromorph
