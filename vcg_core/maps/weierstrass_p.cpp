#include "maps/weierstrass_p.h"

#include <cmath>
#include <limits>

#include "common/errors.h"

namespace meromorph {
namespace {

using Complex = std::complex<double>;
const Complex I(0.0, 1.0);

// Jacobi theta functions theta_k(v | q) with q = exp(i pi tau), and the derivatives of 1 and 2.
struct Thetas {
  Complex t1, t2, t3, t4, d1, d2;
};

Thetas thetas(Complex v, Complex tau) {
  Thetas t{};
  t.t3 = t.t4 = 1.0;
  for (int n = 0; n < 60; ++n) {
    const double half = n + 0.5;
    const Complex q_half = std::exp(I * M_PI * tau * (half * half)); // q^((n+1/2)^2)
    const Complex sine = std::sin(double(2 * n + 1) * v), cosine = std::cos(double(2 * n + 1) * v);
    const double sign = (n % 2) ? -1.0 : 1.0;
    const Complex a1 = 2.0 * sign * q_half * sine, a2 = 2.0 * q_half * cosine;
    t.t1 += a1;
    t.t2 += a2;
    t.d1 += 2.0 * sign * q_half * double(2 * n + 1) * cosine;
    t.d2 -= 2.0 * q_half * double(2 * n + 1) * sine;
    Complex a3 = 0;
    if (n >= 1) {
      const Complex q_n = std::exp(I * M_PI * tau * double(n * n));
      a3 = 2.0 * q_n * std::cos(double(2 * n) * v);
      t.t3 += a3;
      t.t4 += ((n % 2) ? -1.0 : 1.0) * a3;
    }
    const double scale = std::abs(t.t1) + std::abs(t.t2) + std::abs(t.t3) + 1e-300;
    if (n > 2 && (std::abs(a1) + std::abs(a2) + std::abs(a3)) < 1e-18 * scale) break;
  }
  return t;
}

} // namespace

WeierstrassP::WeierstrassP(Complex w1, Complex w2) {
  if (std::abs((w2 / w1).imag()) < 1e-12)
    throw InternalError("the periods of the holomorphic form are parallel");
  // Gauss reduction of the basis.
  for (int step = 0; step < 200; ++step) {
    if (std::abs(w2) < std::abs(w1)) std::swap(w1, w2);
    const double m = std::round((w2 / w1).real());
    if (m == 0) break;
    w2 -= m * w1;
  }
  if ((w2 / w1).imag() < 0) w2 = -w2;
  w1_ = w1;
  w2_ = w2;
  tau_ = w2 / w1;
  q_ = std::exp(I * M_PI * tau_);

  const Thetas at_zero = thetas(0.0, tau_);
  theta2_0_ = at_zero.t2;
  theta3_0_ = at_zero.t3;
  theta4_0_ = at_zero.t4;
  const Complex k2 = (M_PI / w1_) * (M_PI / w1_);
  const Complex t3_4 = std::pow(theta3_0_, 4), t4_4 = std::pow(theta4_0_, 4);
  const Complex e1 = k2 * (t3_4 + t4_4) / 3.0; // P(w1 / 2)
  const Complex e2 = e1 - k2 * t4_4;           // P((w1 + w2) / 2)
  const Complex e3 = e1 - k2 * t3_4;           // P(w2 / 2)
  e1_ = e1;
  e2_ = e3; // roots() follows half_periods(): w1/2, w2/2, (w1+w2)/2
  e3_ = e2;
  g2_ = 2.0 * (e1 * e1 + e2 * e2 + e3 * e3);
  g3_ = 4.0 * e1 * e2 * e3;
}

WeierstrassP::Complex WeierstrassP::reduce(Complex z) const {
  Complex u = z / w1_;
  u -= std::round(u.imag() / tau_.imag()) * tau_;
  u -= std::round(u.real());
  return u;
}

WeierstrassP::Complex WeierstrassP::shortest_representative(Complex z) const {
  // The reduced u is within the parallelogram centred at 0; check its neighbours too.
  const Complex u = reduce(z);
  Complex best = u;
  for (int a = -1; a <= 1; ++a)
    for (int b = -1; b <= 1; ++b) {
      const Complex candidate = u - double(a) - double(b) * tau_;
      if (std::norm(candidate) < std::norm(best)) best = candidate; // squares: no hypot
    }
  return best * w1_;
}

double WeierstrassP::lattice_distance(Complex z) const {
  return std::abs(shortest_representative(z));
}

bool WeierstrassP::is_lattice_point(Complex z, double tolerance) const {
  return std::abs(reduce(z)) <= tolerance;
}

WeierstrassP::Complex WeierstrassP::value(Complex z) const {
  const Complex u = reduce(z);
  if (std::abs(u) < 1e-300) return {std::numeric_limits<double>::infinity(), 0.0};
  // theta1(v) / theta2(v) from the series' terms q^((n+1/2)^2) E^(+-(2n+1)), E = e^(i v), each
  // from the one before by a factor q^(2n+2) E^(+-2): no transcendental function per term, and
  // no power of E on its own (which can overflow where the terms do not). The common factor
  // q^(1/4) of both series cancels in the ratio.
  const Complex v = M_PI * u;
  const Complex e = std::exp(I * v), e_inverse = 1.0 / e;
  const Complex e2 = e * e, e_inverse2 = e_inverse * e_inverse, q2 = q_ * q_;
  Complex up = e, down = e_inverse; // q^((n+1/2)^2 - 1/4) E^(2n+1) and E^-(2n+1)
  Complex q2_power = q2;            // q^(2n+2)
  Complex odd = 0, even = 0;        // sum (-1)^n (up - down), sum (up + down)
  for (int n = 0; n < 60; ++n) {
    const double sign = (n % 2) ? -1.0 : 1.0;
    odd += sign * (up - down);
    even += up + down;
    if (n > 2 && std::abs(up) + std::abs(down) < 1e-18 * (std::abs(odd) + std::abs(even))) break;
    up *= q2_power * e2;
    down *= q2_power * e_inverse2;
    q2_power *= q2;
  }
  // theta2 / theta1 = even / (-i odd)
  const Complex ratio = theta3_0_ * theta4_0_ * even / (-I * odd);
  return e1_ + (M_PI / w1_) * (M_PI / w1_) * ratio * ratio;
}

WeierstrassP::Complex WeierstrassP::derivative(Complex z) const {
  const Complex u = reduce(z);
  if (std::abs(u) < 1e-300) return {std::numeric_limits<double>::infinity(), 0.0};
  const Thetas t = thetas(M_PI * u, tau_);
  const Complex ratio = theta3_0_ * theta4_0_ * t.t2 / t.t1;
  const Complex ratio_dv = theta3_0_ * theta4_0_ * (t.d2 * t.t1 - t.t2 * t.d1) / (t.t1 * t.t1);
  const Complex k = M_PI / w1_;
  return 2.0 * k * k * ratio * ratio_dv * k; // d/dz = (pi / w1) d/dv
}

} // namespace meromorph
