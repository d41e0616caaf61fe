// Periods: the intersection form, a canonical (symplectic) basis, the modulus of a torus and the
// Riemann matrix.
//
// In:  face vectors of closed 1-forms, face geometry; an integer antisymmetric matrix; periods.
// Out: `wedge_matrix`: W_jk = integral of omega_j ^ omega_k = sum_f area_f n . (a_j x a_k), exact
//      for closed forms (their face vectors are Whitney forms), rounded to integers and checked;
//      `symplectic_basis`: an integer unimodular P with P^T W P = J = [[0, I], [-I, 0]];
//      `reduce_modulus`: tau moved by SL(2, Z) into |Re tau| <= 1/2, |tau| >= 1, Im tau > 0.
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Core>

#include "face_vectors.h"

namespace meromorph {

Eigen::MatrixXi wedge_matrix(const std::vector<Eigen::MatrixX3d> &closed_vectors,
                             const FaceGeometry &geometry, double *largest_rounding = nullptr);

Eigen::MatrixXi symplectic_basis(const Eigen::MatrixXi &wedge);

std::complex<double> reduce_modulus(std::complex<double> tau);

} // namespace meromorph
