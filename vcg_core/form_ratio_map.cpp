#include "form_ratio_map.h"

#include <Eigen/Dense>

#include "face_vectors.h"
#include "holomorphic_forms.h"
#include "mesh_edges.h"
#include "sphere_geometry.h"

namespace meromorph {
namespace {

std::vector<Complex> holomorphic_coefficient(const Mesh &mesh, const MeshEdges &edges,
                                             const FaceGeometry &geometry,
                                             const Eigen::VectorXcd &form) {
  const Eigen::MatrixX3d real_part = face_vectors(mesh, edges, geometry, form.real());
  const Eigen::MatrixX3d imaginary_part = face_vectors(mesh, edges, geometry, form.imag());
  return local_coefficients(mesh, geometry, real_part, imaginary_part).f;
}

} // namespace

std::vector<PlaneValue> form_ratio_map(const Mesh &mesh, const MeshEdges &edges,
                                       const Eigen::VectorXcd &numerator,
                                       const Eigen::VectorXcd &denominator) {
  const FaceGeometry geometry = face_geometry(mesh);
  const std::vector<Complex> top = holomorphic_coefficient(mesh, edges, geometry, numerator);
  const std::vector<Complex> bottom = holomorphic_coefficient(mesh, edges, geometry, denominator);
  std::vector<Eigen::Vector3d> face_points(mesh.face.size());
  for (size_t f = 0; f < mesh.face.size(); ++f) {
    const bool pole = std::abs(bottom[f]) == 0.0;
    face_points[f] = to_sphere(PlaneValue{pole ? Complex() : top[f] / bottom[f], pole});
  }
  // The face values are samples at the face centroids; where a vertex's faces differ in size,
  // their mean is the value at a point off the vertex. Fit F = a + b z over the centroids, z in
  // the vertex's tangent plane, F in a chart of the sphere at the faces' mean, and take
  // a = F(vertex). On needle-shaped or one-sided stars the fit extrapolates: a must stay within
  // half the spread of the face values, or the mean is kept.
  const FaceIncidence in = face_incidence(mesh);
  std::vector<PlaneValue> values;
  values.reserve(mesh.vert.size());
  for (size_t v = 0; v < mesh.vert.size(); ++v) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
    for (int f : in.faces_of_vertex[v]) {
      mean += geometry.areas[f] * face_points[f];
      normal += geometry.areas[f] * geometry.normals[f];
    }
    const Eigen::Vector3d centre = mean.normalized();
    normal.normalize();
    const Eigen::Vector3d seed =
        std::abs(normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d e1 = normal.cross(seed).normalized(), e2 = normal.cross(e1);
    const Point3 &origin = mesh.vert[v].cP();
    Eigen::Matrix2cd normal_matrix = Eigen::Matrix2cd::Zero();
    Eigen::Vector2cd right = Eigen::Vector2cd::Zero();
    double spread = 0;
    for (int f : in.faces_of_vertex[v]) {
      const MeshFace &face = mesh.face[f];
      const Point3 c = (face.cP(0) + face.cP(1) + face.cP(2)) / 3.0 - origin;
      const Eigen::Vector3d offset(c[0], c[1], c[2]);
      const Eigen::Vector2cd row(1.0, Complex(offset.dot(e1), offset.dot(e2)));
      const Complex w = chart_at(centre, face_points[f]);
      normal_matrix += geometry.areas[f] * row.conjugate() * row.transpose();
      right += geometry.areas[f] * row.conjugate() * w;
      spread = std::max(spread, std::abs(w));
    }
    const Eigen::Vector2cd fit = normal_matrix.fullPivLu().solve(right);
    const bool trusted = fit.allFinite() && std::abs(fit[0]) <= 0.5 * spread;
    values.push_back(to_plane_value(trusted ? from_chart(centre, fit[0]) : centre));
  }
  return values;
}

} // namespace meromorph
