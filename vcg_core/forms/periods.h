// Periods: the intersection form, a canonical (symplectic) basis, the modulus of a torus and the
// Riemann matrix.
//
// In:  closed 1-forms (values on oriented edges); an integer antisymmetric matrix; periods.
// Out: `wedge_matrix`: W_jk = integral of omega_j ^ omega_k of their Whitney forms, from the edge
//      values alone (on a face with sides a_0, a_1, a_2 and b_0, b_1, b_2 as the face walks them,
//      sum_k (a_k b_k+1 - a_k+1 b_k) / 6: no lengths or angles, so needles and caps cannot spoil
//      it), rounded to integers and checked (`rounded_intersections`: the rounding and the check
//      of such integrals however they were summed; InternalError where one is off by more than
//      1e-3; the pipeline sums them from two sides per face in the conjugate fit's pass over the
//      faces, holomorphic_forms.h, and this sum over all three sides is the reference);
//      `symplectic_basis`: an integer unimodular P with P^T W P = J = [[0, I], [-I, 0]];
//      `reduce_modulus`: tau moved by SL(2, Z) into |Re tau| <= 1/2, |tau| >= 1, Im tau > 0.
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh_edges.h"

namespace meromorph {

Eigen::MatrixXi wedge_matrix(const std::vector<Eigen::VectorXd> &closed_forms,
                             const MeshEdges &edges, double *largest_rounding = nullptr);

Eigen::MatrixXi rounded_intersections(const Eigen::MatrixXd &integrals,
                                      double *largest_rounding = nullptr);

Eigen::MatrixXi symplectic_basis(const Eigen::MatrixXi &wedge);

std::complex<double> reduce_modulus(std::complex<double> tau);

} // namespace meromorph
