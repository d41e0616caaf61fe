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
//      from the normalized forms' edge values (edge by edge over the cores).
#pragma once

#include <array>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace meromorph {

using FormPair = std::pair<Eigen::VectorXcd, Eigen::VectorXcd>;

std::vector<FormPair> generic_form_pairs(int genus);

std::array<Eigen::VectorXcd, 2> ratio_forms(const FormPair &pair,
                                            const std::vector<Eigen::VectorXcd> &normalized);

} // namespace meromorph
