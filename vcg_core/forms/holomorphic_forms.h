// Conjugate harmonic forms, the holomorphic basis and its local coefficients.
//
// In:  face vectors of the 2g harmonic forms h_j (F x 3 each) and the face geometry.
// Out: the conjugate coefficients C (2g x 2g) with *h_j ~ sum_k C_jk h_k, by least squares in the
//      L2 inner product of face vectors (Gram matrix <h_j, h_k> = sum_f area_f <a_j, a_k>), and the
//      relative residual of that fit; holomorphic forms tau_j = h_j + i sum_k C_jk h_k. And per
//      face, for a complex form with real face vectors a and imaginary b, the coefficients of
//      f dz + g dzbar in an orthonormal frame (e1, n x e1): |g| / |f| is the non-holomorphicity.
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Core>

#include "mesh/face_vectors.h"

namespace meromorph {

struct ConjugateFit {
  Eigen::MatrixXd coefficients; // C
  double relative_residual = 0; // max_j |*h_j - sum_k C_jk h_k| / |h_j| in L2
  // From the forms' edge values only (empty from face vectors): W_jk = integral of h_j ^ h_k, per
  // face (a_0 b_1 - a_1 b_0) / 2 from the values along its first two sides, gathered in the same
  // pass (Whitney's sum over all three sides, periods.h wedge_matrix, for closed forms: no
  // lengths or angles either).
  Eigen::MatrixXd intersections;
};

ConjugateFit conjugate_coefficients(const std::vector<Eigen::MatrixX3d> &harmonic_vectors,
                                    const FaceGeometry &geometry);
// The same from the forms' edge values, each face's vectors made as a pass needs them (no array
// of face vectors per form).
ConjugateFit conjugate_coefficients(const FaceCorners &faces, const MeshEdges &edges,
                                    const FaceGeometry &geometry,
                                    const std::vector<Eigen::VectorXd> &harmonic_forms);

struct LocalCoefficients {
  std::vector<std::complex<double>> f, g;
};

LocalCoefficients local_coefficients(const FaceGeometry &geometry,
                                     const Eigen::MatrixX3d &real_part,
                                     const Eigen::MatrixX3d &imaginary_part);
// The same straight from a complex form's edge values, face by face (no arrays of face vectors).
LocalCoefficients local_coefficients(const Mesh &mesh, const MeshEdges &edges,
                                     const FaceGeometry &geometry, const Eigen::VectorXcd &form);
LocalCoefficients local_coefficients(const FaceCorners &faces, const MeshEdges &edges,
                                     const FaceGeometry &geometry, const Eigen::VectorXcd &form);
// The dz coefficients (f of f dz + g dzbar) of complex forms on the mesh's faces, in one pass
// (each face's frame and basis worked out once): column f holds face f's coefficient of each form
// (forms x faces), the same values as local_coefficients(...).f form by form. The coefficient is
// linear in the form: a combination of the forms has the same combination of their columns.
Eigen::MatrixXcd dz_coefficients(const Mesh &mesh, const MeshEdges &edges,
                                 const FaceGeometry &geometry,
                                 const std::vector<Eigen::VectorXcd> &forms);

} // namespace meromorph
