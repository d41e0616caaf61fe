// Tests on values and triangles of the complex plane that decide from squared moduli.
//
// In:  complex values (a triangle's three corners, a difference, a bound). Out: the same answer
//      as the test written with std::abs, which for std::complex<double> is glibc's hypot (and
//      std::norm is its square): squared moduli decide wherever they are clear of the threshold
//      by a millionth, and std::abs decides the near-ties and values whose squares would leave
//      the normal range of doubles (or NaN). The fold checks of the genus-0 maps call these for
//      every face several times: hypot was a sixth of a 4k-vertex map's work.
//      `shorter_than(d, bound)`: !(|d| >= bound) (a NaN is
//      short). `below_resolution(z)`: the triangle's longer edge from z[0] is below 1e-12 of
//      its largest |z[k]| (what doubles resolve). `folded_in_the_plane(z)`: resolved, and its
//      corners turn clockwise or lie on a line.
#pragma once

#include <complex>

namespace meromorph {

inline double squared_modulus(const std::complex<double> &z) {
  return z.real() * z.real() + z.imag() * z.imag();
}

bool shorter_than(const std::complex<double> &difference, double bound);
bool below_resolution(const std::complex<double> z[3]);
bool folded_in_the_plane(const std::complex<double> z[3]);

} // namespace meromorph
