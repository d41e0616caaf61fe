#include "forms/holomorphic_forms.h"

#include <Eigen/Dense>

namespace meromorph {
namespace {

double l2_inner(const Eigen::MatrixX3d &a, const Eigen::MatrixX3d &b,
                const FaceGeometry &geometry) {
  double sum = 0;
  for (long f = 0; f < a.rows(); ++f)
    sum += geometry.areas[f] * a.row(f).dot(b.row(f));
  return sum;
}

Eigen::MatrixX3d star(const Eigen::MatrixX3d &a, const FaceGeometry &geometry) {
  Eigen::MatrixX3d rotated(a.rows(), 3);
  for (long f = 0; f < a.rows(); ++f)
    rotated.row(f) = geometry.normals[f].cross(Eigen::Vector3d(a.row(f)));
  return rotated;
}

} // namespace

Eigen::MatrixX3d combine(const std::vector<Eigen::MatrixX3d> &vectors,
                         const Eigen::VectorXd &coefficients) {
  Eigen::MatrixX3d sum = Eigen::MatrixX3d::Zero(vectors.front().rows(), 3);
  for (size_t k = 0; k < vectors.size(); ++k)
    sum += coefficients[long(k)] * vectors[k];
  return sum;
}

ConjugateFit conjugate_coefficients(const std::vector<Eigen::MatrixX3d> &harmonic_vectors,
                                    const FaceGeometry &geometry) {
  const long n = long(harmonic_vectors.size());
  Eigen::MatrixXd gram(n, n), starred(n, n);
  std::vector<Eigen::MatrixX3d> stars;
  for (long j = 0; j < n; ++j)
    stars.push_back(star(harmonic_vectors[j], geometry));
  for (long j = 0; j < n; ++j)
    for (long k = 0; k < n; ++k) {
      gram(j, k) = l2_inner(harmonic_vectors[j], harmonic_vectors[k], geometry);
      starred(j, k) = l2_inner(stars[j], harmonic_vectors[k], geometry);
    }
  ConjugateFit fit;
  fit.coefficients = gram.ldlt().solve(starred.transpose()).transpose(); // C = S G^-1
  for (long j = 0; j < n; ++j) {
    const Eigen::MatrixX3d error =
        stars[j] - combine(harmonic_vectors, fit.coefficients.row(j).transpose());
    fit.relative_residual =
        std::max(fit.relative_residual, std::sqrt(l2_inner(error, error, geometry) / gram(j, j)));
  }
  return fit;
}

LocalCoefficients local_coefficients(const FaceGeometry &geometry,
                                     const Eigen::MatrixX3d &real_part,
                                     const Eigen::MatrixX3d &imaginary_part) {
  const size_t face_count = geometry.areas.size();
  LocalCoefficients local;
  local.f.reserve(face_count);
  local.g.reserve(face_count);
  for (size_t f = 0; f < face_count; ++f) {
    const Eigen::Vector3d &e1 = geometry.first_axes[f];
    const Eigen::Vector3d e2 = geometry.normals[f].cross(e1);
    const Eigen::Vector3d a = real_part.row(long(f)), b = imaginary_part.row(long(f));
    const double ax = a.dot(e1), ay = a.dot(e2), bx = b.dot(e1), by = b.dot(e2);
    local.f.emplace_back((ax + by) / 2, (bx - ay) / 2);
    local.g.emplace_back((ax - by) / 2, (bx + ay) / 2);
  }
  return local;
}

} // namespace meromorph
