#include "form_ratio_map.h"

#include "face_vectors.h"
#include "holomorphic_forms.h"
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
  std::vector<Eigen::Vector3d> sum(mesh.vert.size(), Eigen::Vector3d::Zero());
  for (size_t f = 0; f < mesh.face.size(); ++f) {
    const bool pole = std::abs(bottom[f]) == 0.0;
    const PlaneValue value{pole ? Complex() : top[f] / bottom[f], pole};
    const Eigen::Vector3d point = to_sphere(value);
    for (int k = 0; k < 3; ++k)
      sum[index_of(mesh, mesh.face[f].cV(k))] += geometry.areas[f] * point;
  }
  std::vector<PlaneValue> values;
  values.reserve(sum.size());
  for (const Eigen::Vector3d &p : sum)
    values.push_back(to_plane_value(p.normalized()));
  return values;
}

} // namespace meromorph
