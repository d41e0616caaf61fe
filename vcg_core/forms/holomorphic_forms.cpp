#include "forms/holomorphic_forms.h"

#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "common/parallel_for.h"

namespace meromorph {

namespace {

// C from the forms' face vectors, `columns(f, in_frame)` putting face f's vector of every form
// side by side, in the face's frame (e1, n x e1). There *h = (-y, x) for h = (x, y), so that
// <h_j, h_k> = <x_j, x_k> + <y_j, y_k>, <*h_j, h_k> = <x_j, y_k> - <y_j, x_k> and
// |*h_j| = |h_j|: one pass over the faces gathers all from the area-weighted Gram matrix of the
// columns (x_1 .. x_n, y_1 .. y_n), a rank update per chunk of faces. `with_sides`: `columns(f,
// in_frame, sides)` also gives the forms' values along face f's first two sides (the rows of
// `sides`), and the same pass sums P_jk = sum_f a_0j a_1k for the intersections W = (P - P^T) / 2.
template <class Columns>
ConjugateFit conjugate_fit(long n, size_t face_count, const FaceGeometry &geometry, bool with_sides,
                           const Columns &columns) {
  // The Gram matrix's lower triangle beside P (its first 2n columns, P the last n).
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(2 * n, 3 * n);
  const Eigen::MatrixXd sums = chunked_sum(face_count, zero, [&](size_t begin, size_t end) {
    Eigen::MatrixXd sum = zero;
    Eigen::MatrixXd rows(long(stacked_block), 2 * n); // common/parallel_for.h
    Eigen::MatrixXd first_sides(long(stacked_block), n), second_sides(long(stacked_block), n);
    Eigen::Matrix2Xd in_frame(2, n), sides(2, n); // no allocation per face
    for (size_t first = begin; first < end; first += stacked_block) {
      const size_t last = std::min(end, first + stacked_block);
      for (size_t f = first; f < last; ++f) {
        columns(f, in_frame, sides);
        const double weight = std::sqrt(geometry.areas[f]);
        rows.row(long(f - first)) << weight * in_frame.row(0), weight * in_frame.row(1);
        first_sides.row(long(f - first)) = sides.row(0);
        second_sides.row(long(f - first)) = sides.row(1);
      }
      const long count = long(last - first);
      sum.leftCols(2 * n).selfadjointView<Eigen::Lower>().rankUpdate(
          rows.topRows(count).transpose());
      if (with_sides)
        sum.block(0, 2 * n, n, n).noalias() +=
            first_sides.topRows(count).transpose() * second_sides.topRows(count);
    }
    return sum;
  });
  const Eigen::MatrixXd inner = sums.leftCols(2 * n).selfadjointView<Eigen::Lower>();
  const Eigen::MatrixXd xy = inner.bottomLeftCorner(n, n).transpose(); // <x_j, y_k>
  const Eigen::MatrixXd gram = inner.topLeftCorner(n, n) + inner.bottomRightCorner(n, n);
  const Eigen::MatrixXd starred = xy - xy.transpose(); // S = <*h_j, h_k>
  ConjugateFit fit;
  fit.coefficients = gram.ldlt().solve(starred.transpose()).transpose(); // C = S G^-1
  // |*h_j - sum_l C_jl h_l|^2 = |h_j|^2 - 2 (C S^T)_jj + (C G C^T)_jj.
  const Eigen::MatrixXd &c = fit.coefficients;
  const Eigen::MatrixXd error = gram - 2.0 * c * starred.transpose() + c * gram * c.transpose();
  for (long j = 0; j < n; ++j)
    fit.relative_residual =
        std::max(fit.relative_residual, std::sqrt(std::max(0.0, error(j, j)) / gram(j, j)));
  if (with_sides) {
    const Eigen::MatrixXd products = sums.block(0, 2 * n, n, n);
    fit.intersections = (products - products.transpose()) / 2.0;
  }
  return fit;
}

// Face f's two basis vectors (face_vector_basis) in the face's frame: a complex form's face vector
// is u1 first + u2 second with u1, u2 its values along the face's first two sides. In the frame
// (e1 along side u = p1 - p0, e2 = n x e1), with d = p2 - p0, L = |u| and A the area,
// first = n x (p0 - p2) / 2A = (1 / L, -u.d / (2A L)) and second = n x u / 2A = (0, L / 2A):
// the sides' lengths and one dot product, no normal or frame (those were most of the time of
// the ratio's per-face samples). NaN where the face has no area, as the vectors were.
struct BasisInFrame {
  double first_x, second_x, first_y, second_y;
};

BasisInFrame basis_in_frame(const FaceGeometry &geometry, size_t f) {
  const auto [u, d] = geometry.sides(f);
  const double length = u.norm(), twice_area = 2.0 * geometry.areas[f];
  if (!(length > 0) || !(twice_area > 0)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan, nan};
  }
  return {1.0 / length, 0.0, -u.dot(d) / (twice_area * length), length / twice_area};
}

// (cx, cy): the complex form's face vector on face f in the face's frame.
std::array<std::complex<double>, 2> in_frame(const BasisInFrame &basis, const MeshEdges &edges,
                                             size_t f, const Eigen::VectorXcd &form) {
  const std::complex<double> u1 = double(edges.face_signs[f][0]) * form[edges.face_edges[f][0]];
  const std::complex<double> u2 =
      u1 + double(edges.face_signs[f][1]) * form[edges.face_edges[f][1]];
  return {u1 * basis.first_x + u2 * basis.second_x, u1 * basis.first_y + u2 * basis.second_y};
}

// f dz + g dzbar on each face of `geometry`'s faces for a complex form: with c the complex face
// vector and (cx, cy) its components in the face's frame, f = (cx - i cy) / 2 and
// g = (cx + i cy) / 2.
LocalCoefficients coefficients_of(size_t face_count, const MeshEdges &edges,
                                  const FaceGeometry &geometry, const Eigen::VectorXcd &form) {
  LocalCoefficients local;
  local.f.resize(face_count);
  local.g.resize(face_count);
  const std::complex<double> i(0, 1);
  parallel_for(face_count, [&](size_t f) {
    const auto [cx, cy] = in_frame(basis_in_frame(geometry, f), edges, f, form);
    local.f[f] = (cx - i * cy) / 2.0;
    local.g[f] = (cx + i * cy) / 2.0;
  });
  return local;
}

// A vector in the plane of a face, in the face's frame.
Eigen::Vector2d in_face_frame(const FaceFrame &frame, const Eigen::Vector3d &v) {
  const Eigen::Vector3d &e1 = frame.first_axis;
  return {v.dot(e1), v.dot(frame.normal.cross(e1))};
}

} // namespace

ConjugateFit conjugate_coefficients(const std::vector<Eigen::MatrixX3d> &harmonic_vectors,
                                    const FaceGeometry &geometry) {
  const long n = long(harmonic_vectors.size());
  return conjugate_fit(n, size_t(harmonic_vectors.front().rows()), geometry, false,
                       [&](size_t f, Eigen::Matrix2Xd &in_frame, Eigen::Matrix2Xd &) {
                         const FaceFrame frame = geometry.frame(f);
                         for (long j = 0; j < n; ++j)
                           in_frame.col(j) = in_face_frame(
                               frame, harmonic_vectors[size_t(j)].row(long(f)).transpose());
                       });
}

ConjugateFit conjugate_coefficients(const FaceCorners &faces, const MeshEdges &edges,
                                    const FaceGeometry &geometry,
                                    const std::vector<Eigen::VectorXd> &harmonic_forms) {
  const long n = long(harmonic_forms.size());
  return conjugate_fit(n, faces.size(), geometry, true,
                       [&](size_t f, Eigen::Matrix2Xd &in_frame, Eigen::Matrix2Xd &sides) {
                         const BasisInFrame basis = basis_in_frame(geometry, f);
                         const Eigen::Vector2d first(basis.first_x, basis.first_y);
                         const Eigen::Vector2d second(basis.second_x, basis.second_y);
                         const int e0 = edges.face_edges[f][0], e1 = edges.face_edges[f][1];
                         const double s0 = edges.face_signs[f][0], s1 = edges.face_signs[f][1];
                         for (long j = 0; j < n; ++j) {
                           const Eigen::VectorXd &form = harmonic_forms[size_t(j)];
                           const double along_first = s0 * form[e0], along_second = s1 * form[e1];
                           const double u1 = along_first, u2 = u1 + along_second;
                           in_frame.col(j) = u1 * first + u2 * second;
                           sides.col(j) << along_first, along_second;
                         }
                       });
}

LocalCoefficients local_coefficients(const FaceGeometry &geometry,
                                     const Eigen::MatrixX3d &real_part,
                                     const Eigen::MatrixX3d &imaginary_part) {
  const size_t face_count = geometry.areas.size();
  LocalCoefficients local;
  local.f.resize(face_count);
  local.g.resize(face_count);
  parallel_for(face_count, [&](size_t f) {
    const FaceFrame frame = geometry.frame(f);
    const Eigen::Vector3d &e1 = frame.first_axis;
    const Eigen::Vector3d e2 = frame.normal.cross(e1);
    const Eigen::Vector3d a = real_part.row(long(f)), b = imaginary_part.row(long(f));
    const double ax = a.dot(e1), ay = a.dot(e2), bx = b.dot(e1), by = b.dot(e2);
    local.f[f] = {(ax + by) / 2, (bx - ay) / 2};
    local.g[f] = {(ax - by) / 2, (bx + ay) / 2};
  });
  return local;
}

LocalCoefficients local_coefficients(const Mesh &mesh, const MeshEdges &edges,
                                     const FaceGeometry &geometry, const Eigen::VectorXcd &form) {
  return coefficients_of(mesh.face.size(), edges, geometry, form);
}

LocalCoefficients local_coefficients(const FaceCorners &faces, const MeshEdges &edges,
                                     const FaceGeometry &geometry, const Eigen::VectorXcd &form) {
  return coefficients_of(faces.size(), edges, geometry, form);
}

Eigen::MatrixXcd dz_coefficients(const Mesh &mesh, const MeshEdges &edges,
                                 const FaceGeometry &geometry,
                                 const std::vector<Eigen::VectorXcd> &forms) {
  const size_t face_count = mesh.face.size();
  Eigen::MatrixXcd out(long(forms.size()), long(face_count));
  parallel_for(face_count, [&](size_t f) {
    const BasisInFrame basis = basis_in_frame(geometry, f);
    for (size_t k = 0; k < forms.size(); ++k) {
      const auto [x, y] = in_frame(basis, edges, f, forms[k]);
      // (x - i y) / 2 in real arithmetic: the same bits, without a complex product per form.
      out(long(k), long(f)) = {(x.real() + y.imag()) / 2.0, (x.imag() - y.real()) / 2.0};
    }
  });
  return out;
}

} // namespace meromorph
