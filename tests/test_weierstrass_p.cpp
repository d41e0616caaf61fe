// The Weierstrass P-function against its definition and its differential equation.
#include <gtest/gtest.h>

#include "maps/weierstrass_p.h"

namespace meromorph {
namespace {

using Complex = std::complex<double>;

Complex lattice_sum(Complex z, Complex w1, Complex w2) {
  Complex sum = 1.0 / (z * z);
  const int n = 300;
  for (int a = -n; a <= n; ++a)
    for (int b = -n; b <= n; ++b) {
      if (!a && !b) continue;
      const Complex w = double(a) * w1 + double(b) * w2;
      sum += 1.0 / ((z - w) * (z - w)) - 1.0 / (w * w);
    }
  return sum;
}

TEST(WeierstrassP, MatchesTheLatticeSumAndItsDifferentialEquation) {
  const std::pair<Complex, Complex> lattices[] = {
      {Complex(1, 0), Complex(0, 1)},           // square
      {Complex(1, 0), Complex(0.5, 0.8660254)}, // hexagonal
      {Complex(1, 0), Complex(0.3, 1.7)},       // general
      {Complex(0.7, 0.2), Complex(-1.9, 2.6)},  // unreduced basis
      {Complex(1, 0), Complex(0.2, 12)},        // long and thin (a thin torus's flat image)
  };
  for (const auto &[w1, w2] : lattices) {
    const WeierstrassP p(w1, w2);
    for (const Complex z : {Complex(0.23, 0.17), Complex(-0.31, 0.05), Complex(0.4, -0.33)}) {
      const Complex value = p.value(z), sum = lattice_sum(z, w1, w2);
      EXPECT_LT(std::abs(value - sum), 2e-4 * std::abs(sum)) << w2 << " " << z; // sum truncation
      const Complex d = p.derivative(z);
      const Complex lhs = d * d, rhs = 4.0 * value * value * value - p.g2() * value - p.g3();
      EXPECT_LT(std::abs(lhs - rhs), 1e-9 * std::abs(lhs)) << w2 << " " << z;
      // Double periodicity.
      EXPECT_LT(std::abs(p.value(z + w1) - value), 1e-9 * std::abs(value));
      EXPECT_LT(std::abs(p.value(z - 2.0 * w2) - value), 1e-9 * std::abs(value));
      // The derivative against a central difference.
      const double h = 1e-5;
      const Complex numeric = (p.value(z + h) - p.value(z - h)) / (2 * h);
      EXPECT_LT(std::abs(numeric - d), 1e-5 * std::abs(d));
    }
    // P' vanishes at the half periods, where P takes the roots of 4x^3 - g2 x - g3.
    for (int k = 0; k < 3; ++k) {
      const Complex h = p.half_periods()[k], e = p.roots()[k];
      EXPECT_LT(std::abs(p.derivative(h)), 1e-8 * std::abs(p.g2()));
      EXPECT_LT(std::abs(p.value(h) - e), 1e-10 * std::abs(e) + 1e-12);
      EXPECT_LT(std::abs(4.0 * e * e * e - p.g2() * e - p.g3()),
                1e-9 * std::abs(p.g2() * e) + 1e-9);
    }
    EXPECT_TRUE(p.is_lattice_point(w1 + w2, 1e-12));
    EXPECT_GE(std::abs(p.tau()), 1.0 - 1e-12);
    EXPECT_LE(std::abs(p.tau().real()), 0.5 + 1e-12);
  }
}

} // namespace
} // namespace meromorph
