#include "sphere/plane_triangles.h"

#include <algorithm>
#include <cmath>

namespace meromorph {
namespace {

// Squares are exact to a few units in the last place within this range; a millionth of margin
// leaves only true near-ties to std::abs.
constexpr double smallest_square = 1e-270, largest_square = 1e270, margin = 1e-6;

bool in_range(double square) {
  return square > smallest_square && square < largest_square;
}

// |a| < |b| * factor from squares where that is clear: 1 (yes), 0 (no), -1 (too close to call).
int less_by_squares(double a_square, double b_square_times_factor_square) {
  if (!(a_square < largest_square) || !in_range(b_square_times_factor_square)) return -1;
  if (a_square < b_square_times_factor_square * (1 - margin)) return 1;
  if (a_square > b_square_times_factor_square * (1 + margin)) return 0;
  return -1;
}

} // namespace

bool shorter_than(const std::complex<double> &difference, double bound) {
  const int clear = bound > 0 ? less_by_squares(squared_modulus(difference), bound * bound) : -1;
  return clear >= 0 ? clear == 1 : !(std::abs(difference) >= bound);
}

bool below_resolution(const std::complex<double> z[3]) {
  constexpr double resolution = 1e-12;
  const double size_square = std::max(squared_modulus(z[1] - z[0]), squared_modulus(z[2] - z[0]));
  const double distance_square =
      std::max({squared_modulus(z[0]), squared_modulus(z[1]), squared_modulus(z[2])});
  const int clear = less_by_squares(size_square, resolution * resolution * distance_square);
  if (clear >= 0) return clear == 1;
  const double size = std::max(std::abs(z[1] - z[0]), std::abs(z[2] - z[0]));
  const double distance = std::max({std::abs(z[0]), std::abs(z[1]), std::abs(z[2])});
  return size < resolution * distance;
}

bool folded_in_the_plane(const std::complex<double> z[3]) {
  if (below_resolution(z)) return false;
  return std::imag(std::conj(z[1] - z[0]) * (z[2] - z[0])) <= 0;
}

} // namespace meromorph
