// The generic pairs of holomorphic 1-forms whose ratio is the genus >= 2 map.
//
// In:  the genus g >= 2.
// Out: pairs (a, b) of coefficient vectors, omega1 = sum a_k psi_k and omega2 = sum b_k psi_k over
//      the normalized forms psi_k, in the order they are tried. A single normalized form lives on
//      its own handle and nearly vanishes on the others, so every a_k and b_k is non-zero, and
//      their ratios a_k / b_k differ from handle to handle: first unit coefficients spread around
//      the circle (a_k = exp(2 pi i k / g), b_k = exp(i (4 pi k / g + 0.7))), then the earlier
//      default (1 and (k + 1) / (g + 1)), then pseudo-random unit coefficients from a fixed seed
//      (the same list on every machine).
//      `ratio_forms`: a pair's numerator omega1 + omega2 and denominator omega1 - omega2 per edge,
//      from the normalized forms' edge values (edge by edge over the cores). `ratio_dz`: the
//      same two forms' dz coefficients per face, from the normalized forms' (dz_coefficients in
//      holomorphic_forms.h, forms x faces): the dz coefficient is linear in the form, so a pair's
//      is the same combination of the normalized forms' columns (face by face over the cores; the
//      same values up to rounding as dz_coefficients of ratio_forms' two).
#pragma once

#include <array>
#include <complex>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace meromorph {

using FormPair = std::pair<Eigen::VectorXcd, Eigen::VectorXcd>;

std::vector<FormPair> generic_form_pairs(int genus);

std::array<Eigen::VectorXcd, 2> ratio_forms(const FormPair &pair,
                                            const std::vector<Eigen::VectorXcd> &normalized);

std::array<std::vector<std::complex<double>>, 2> ratio_dz(const FormPair &pair,
                                                          const Eigen::MatrixXcd &normalized_dz);

} // namespace meromorph
