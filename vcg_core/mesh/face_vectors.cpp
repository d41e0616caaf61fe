#include "mesh/face_vectors.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "common/parallel_for.h"

namespace meromorph {
namespace {

// Corner k of face f, as Eigen vectors, from either kind of faces.
Eigen::Vector3d corner(const Mesh &mesh, size_t f, int k) {
  return mesh.face[f].cP(k).ToEigenVector<Eigen::Vector3d>();
}
Eigen::Vector3d corner(const FaceCorners &faces, size_t f, int k) {
  return faces[f][size_t(k)];
}

template <class Faces> std::vector<double> areas_of(const Faces &faces, size_t face_count) {
  std::vector<double> areas(face_count);
  parallel_for(face_count, [&](size_t f) {
    const Eigen::Vector3d p0 = corner(faces, f, 0), p1 = corner(faces, f, 1),
                          p2 = corner(faces, f, 2);
    areas[f] = 0.5 * (p1 - p0).cross(p2 - p0).norm();
  });
  return areas;
}

template <class Faces>
FaceVectorBasis basis_of(const Faces &faces, const FaceGeometry &geometry, size_t f) {
  const Eigen::Vector3d p0 = corner(faces, f, 0), p1 = corner(faces, f, 1),
                        p2 = corner(faces, f, 2);
  const Eigen::Vector3d n = geometry.normal(f);
  // grad phi_i = n x (edge opposite corner i, counter-clockwise) / (2 area); the local potential
  // is u0 = 0, u1 = form along side 0, u2 = u1 + form along side 1.
  return {n.cross(p0 - p2) / (2.0 * geometry.areas[f]),
          n.cross(p1 - p0) / (2.0 * geometry.areas[f])};
}

template <class Faces>
Eigen::Vector3d vector_of(const Faces &faces, const MeshEdges &edges, const FaceGeometry &geometry,
                          const Eigen::VectorXd &form, size_t f) {
  const FaceVectorBasis basis = basis_of(faces, geometry, f);
  const double u1 = edges.face_signs[f][0] * form[edges.face_edges[f][0]];
  const double u2 = u1 + edges.face_signs[f][1] * form[edges.face_edges[f][1]];
  return u1 * basis.first + u2 * basis.second;
}

template <class Faces>
Eigen::MatrixX3d vectors_of(const Faces &faces, size_t face_count, const MeshEdges &edges,
                            const FaceGeometry &geometry, const Eigen::VectorXd &form) {
  Eigen::MatrixX3d vectors(face_count, 3);
  parallel_for(face_count, [&](size_t f) {
    vectors.row(long(f)) = vector_of(faces, edges, geometry, form, f).transpose();
  });
  return vectors;
}

} // namespace

FaceGeometry face_geometry(const Mesh &mesh) {
  FaceGeometry geometry;
  geometry.areas = areas_of(mesh, mesh.face.size());
  geometry.mesh_ = &mesh;
  return geometry;
}

FaceGeometry face_geometry(const FaceCorners &faces) {
  FaceGeometry geometry;
  geometry.areas = areas_of(faces, faces.size());
  geometry.corners_ = &faces;
  return geometry;
}

Eigen::Vector3d FaceGeometry::corner(size_t f, int k) const {
  return mesh_ ? meromorph::corner(*mesh_, f, k) : meromorph::corner(*corners_, f, k);
}

std::array<Eigen::Vector3d, 2> FaceGeometry::sides(size_t f) const {
  const Eigen::Vector3d p0 = corner(f, 0);
  return {corner(f, 1) - p0, corner(f, 2) - p0};
}

Eigen::Vector3d FaceGeometry::normal(size_t f) const {
  const auto [u, d] = sides(f);
  return u.cross(d).normalized();
}

FaceFrame FaceGeometry::frame(size_t f) const {
  const auto [u, d] = sides(f);
  return {u.cross(d).normalized(), u.normalized()};
}

double corner_angle(const MeshFace &face, int k) {
  const Point3 u = face.cP((k + 1) % 3) - face.cP(k), w = face.cP((k + 2) % 3) - face.cP(k);
  return std::atan2((u ^ w).Norm(), u * w);
}

double corner_angle(const Eigen::Vector3d &at, const Eigen::Vector3d &to,
                    const Eigen::Vector3d &from) {
  const Eigen::Vector3d u = to - at, v = from - at;
  return std::atan2(u.cross(v).norm(), u.dot(v));
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
  return vectors_of(mesh, mesh.face.size(), edges, geometry, form);
}

Eigen::MatrixX3d face_vectors(const FaceCorners &faces, const MeshEdges &edges,
                              const FaceGeometry &geometry, const Eigen::VectorXd &form) {
  return vectors_of(faces, faces.size(), edges, geometry, form);
}

FaceVectorBasis face_vector_basis(const FaceCorners &faces, const FaceGeometry &geometry,
                                  size_t f) {
  return basis_of(faces, geometry, f);
}

FaceVectorBasis face_vector_basis(const Mesh &mesh, const FaceGeometry &geometry, size_t f) {
  return basis_of(mesh, geometry, f);
}

} // namespace meromorph
