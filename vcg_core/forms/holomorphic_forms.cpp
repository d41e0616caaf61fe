#include "forms/holomorphic_forms.h"

#include <Eigen/Dense>

#include "common/parallel_for.h"

namespace meromorph {

namespace {

// C from the forms' face vectors, `columns(f, plain)` putting face f's vector of every form side
// by side (one pass for the inner products, one for the residual).
template <class Columns>
ConjugateFit conjugate_fit(long n, size_t face_count, const FaceGeometry &geometry,
                           const Columns &columns) {
  // The face's vectors, and turned a quarter about the normal (*).
  auto both = [&](size_t f, Eigen::Matrix3Xd &plain, Eigen::Matrix3Xd &starred) {
    columns(f, plain);
    for (long j = 0; j < n; ++j)
      starred.col(j) = geometry.normals[f].cross(Eigen::Vector3d(plain.col(j)));
  };
  // G = <h_j, h_k> and S = <*h_j, h_k> (L2 over the faces), in one pass over the faces.
  struct Inner {
    Eigen::MatrixXd gram, starred;
    Inner &operator+=(const Inner &other) {
      gram += other.gram;
      starred += other.starred;
      return *this;
    }
  };
  const Inner zero{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, n)};
  const Inner inner = chunked_sum(face_count, zero, [&](size_t begin, size_t end) {
    Inner sum = zero;
    Eigen::Matrix3Xd plain(3, n), starred(3, n), weighted(3, n); // no allocation per face
    for (size_t f = begin; f < end; ++f) {
      both(f, plain, starred);
      weighted = geometry.areas[f] * plain;
      sum.gram.noalias() += weighted.transpose().lazyProduct(plain);
      sum.starred.noalias() += starred.transpose().lazyProduct(weighted);
    }
    return sum;
  });
  ConjugateFit fit;
  fit.coefficients = inner.gram.ldlt().solve(inner.starred.transpose()).transpose(); // C = S G^-1
  // |*h_j - sum_l C_jl h_l|^2 for every j, in one pass.
  const Eigen::VectorXd no_error = Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd error_squared =
      chunked_sum(face_count, no_error, [&](size_t begin, size_t end) {
        Eigen::VectorXd sum = no_error;
        Eigen::Matrix3Xd plain(3, n), starred(3, n), error(3, n); // no allocation per face
        for (size_t f = begin; f < end; ++f) {
          both(f, plain, starred);
          error = starred;
          error.noalias() -= plain.lazyProduct(fit.coefficients.transpose());
          for (long j = 0; j < n; ++j)
            sum[j] += geometry.areas[f] * error.col(j).squaredNorm();
        }
        return sum;
      });
  for (long j = 0; j < n; ++j)
    fit.relative_residual =
        std::max(fit.relative_residual, std::sqrt(error_squared[j] / inner.gram(j, j)));
  return fit;
}

} // namespace

ConjugateFit conjugate_coefficients(const std::vector<Eigen::MatrixX3d> &harmonic_vectors,
                                    const FaceGeometry &geometry) {
  const long n = long(harmonic_vectors.size());
  return conjugate_fit(n, size_t(harmonic_vectors.front().rows()), geometry,
                       [&](size_t f, Eigen::Matrix3Xd &plain) {
                         for (long j = 0; j < n; ++j)
                           plain.col(j) = harmonic_vectors[size_t(j)].row(long(f)).transpose();
                       });
}

ConjugateFit conjugate_coefficients(const FaceCorners &faces, const MeshEdges &edges,
                                    const FaceGeometry &geometry,
                                    const std::vector<Eigen::VectorXd> &harmonic_forms) {
  const long n = long(harmonic_forms.size());
  return conjugate_fit(n, faces.size(), geometry, [&](size_t f, Eigen::Matrix3Xd &plain) {
    const FaceVectorBasis basis = face_vector_basis(faces, geometry, f);
    const int e0 = edges.face_edges[f][0], e1 = edges.face_edges[f][1];
    const double s0 = edges.face_signs[f][0], s1 = edges.face_signs[f][1];
    for (long j = 0; j < n; ++j) {
      const Eigen::VectorXd &form = harmonic_forms[size_t(j)];
      const double u1 = s0 * form[e0], u2 = u1 + s1 * form[e1];
      plain.col(j) = u1 * basis.first + u2 * basis.second;
    }
  });
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
