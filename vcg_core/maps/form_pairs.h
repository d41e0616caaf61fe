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
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

namespace meromorph {

using FormPair = std::pair<Eigen::VectorXcd, Eigen::VectorXcd>;

std::vector<FormPair> generic_form_pairs(int genus);

} // namespace meromorph
