// The Weierstrass P-function of a lattice, through Jacobi theta functions.
//
// In:  a lattice w1 Z + w2 Z (any basis, w2 / w1 not real) and a point z.
// Out: `WeierstrassP` reduces the basis to one whose ratio tau lies in the standard fundamental
//      domain (|Re tau| <= 1/2, |tau| >= 1, Im tau > 0), then evaluates P(z) and P'(z) after
//      moving z into the period parallelogram centred at 0, with
//        P(z) = e1 + (pi / w1)^2 (theta3 theta4 theta2(v) / theta1(v))^2,  v = pi z / w1
//      (DLMF 23.6.2 and 23.6.5 with 2 omega1 = w1), which converges fast since |q| <= e^(-pi sqrt3
//      / 2). Also g2, g3 (P'^2 = 4 P^3 - g2 P - g3) and the half periods where P' = 0.
#pragma once

#include <array>
#include <complex>

namespace meromorph {

class WeierstrassP {
public:
  using Complex = std::complex<double>;

  WeierstrassP(Complex w1, Complex w2);

  Complex value(Complex z) const;      // P(z); infinite at lattice points
  Complex derivative(Complex z) const; // P'(z)
  bool is_lattice_point(Complex z, double tolerance) const;
  double lattice_distance(Complex z) const;         // distance from z to the nearest lattice point
  Complex shortest_representative(Complex z) const; // z minus the lattice point nearest it

  Complex g2() const { return g2_; }
  Complex g3() const { return g3_; }
  Complex tau() const { return tau_; }
  std::array<Complex, 2> periods() const { return {w1_, w2_}; } // the reduced basis, tau = w2 / w1
  std::array<Complex, 3> half_periods() const { return {w1_ / 2.0, w2_ / 2.0, (w1_ + w2_) / 2.0}; }
  std::array<Complex, 3> roots() const { return {e1_, e2_, e3_}; } // P at the half periods

private:
  Complex reduce(Complex z) const; // z moved into the parallelogram centred at 0 (units of w1)

  Complex w1_, w2_, tau_, q_;
  Complex theta2_0_, theta3_0_, theta4_0_;
  Complex e1_, e2_, e3_, g2_, g3_;
};

} // namespace meromorph
