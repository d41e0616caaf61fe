// Geometry of the Riemann sphere: stereographic projection, spherical triangles, charts.
//
// In:  points of the unit sphere (Eigen::Vector3d) or of the extended complex plane.
// Out: `to_sphere(w)` is the inverse stereographic projection from the north pole (0, 0, 1):
//      w = (x - i y) / (1 - z), with infinity at the north pole; `to_plane(p)` its inverse. (The
//      sign of y makes the projection preserve orientation for outward normals, so a holomorphic
//      map gives positively oriented sphere triangles; design.md writes x + i y, its mirror image.)
//      `signed_solid_angle(a, b, c)` the signed area of the spherical triangle (positive when
//      a, b, c turn counter-clockwise seen from outside); `chart_at(p)` the stereographic
//      coordinate of a chart centred at p (p -> 0, its antipode -> infinity),
//      orientation-preserving.
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Core>

namespace meromorph {

using Complex = std::complex<double>;

// A value of the extended plane: finite, or infinity (the north pole).
struct PlaneValue {
  Complex w;
  bool infinite = false;
};

Eigen::Vector3d to_sphere(const Complex &w);
Eigen::Vector3d to_sphere(const PlaneValue &value);
std::vector<Eigen::Vector3d> to_sphere(const std::vector<PlaneValue> &values); // each value
Complex to_plane(const Eigen::Vector3d &p); // the north pole itself maps to a huge value

double signed_solid_angle(const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                          const Eigen::Vector3d &c);
// Whether the signed solid angle is certainly above `threshold` (>= 0, far below pi) without
// its arctangent: 2 atan2(n, d) >= (pi / 2) min(n / d, 1) for n > 0. False where that does not
// settle it (then ask signed_solid_angle).
bool solid_angle_clearly_above(const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                               const Eigen::Vector3d &c, double threshold);

// The angle from a to b seen from `center` in its chart, in (-pi + 0.05, pi + 0.05]: a turn of
// about a half counts as positive. A double point doubles the corners at its vertex, and a corner
// of 90 degrees (or a little more) there comes out as a half turn that rounding may sign either
// way.
double swept_angle(const Eigen::Vector3d &center, const Eigen::Vector3d &a,
                   const Eigen::Vector3d &b);

// A face image turned over: negative signed area beyond rounding (1e-9 of its longest chord
// squared); an image that is flat to rounding is degenerate, not folded.
bool folded_image(const Eigen::Vector3d &a, const Eigen::Vector3d &b, const Eigen::Vector3d &c);
// As a reader of the written positions sees a face image: its chord triangle not positively
// oriented by more than `margin` times its longest side squared (flat ones count when margin > 0).
bool chord_turned_over(const Eigen::Vector3d &a, const Eigen::Vector3d &b, const Eigen::Vector3d &c,
                       double margin);
// The image triangle's longest side is below 1e-14: smaller than doubles resolve on the unit
// sphere (long thin parts shrink exponentially under a conformal map).
bool collapsed_image(const Eigen::Vector3d &a, const Eigen::Vector3d &b, const Eigen::Vector3d &c);

// Stereographic coordinate of q in the chart centred at p (both unit vectors).
Complex chart_at(const Eigen::Vector3d &p, const Eigen::Vector3d &q);

PlaneValue to_plane_value(const Eigen::Vector3d &p); // the north pole gives infinity

// The sphere point whose coordinate in the chart centred at p is w (inverse of chart_at).
Eigen::Vector3d from_chart(const Eigen::Vector3d &p, const Complex &w);

// A Moebius transformation w -> (a w + b) / (c w + d), acting on the extended plane.
struct Mobius {
  Complex a{1, 0}, b{0, 0}, c{0, 0}, d{1, 0};

  PlaneValue apply(const PlaneValue &value) const;
  Mobius after(const Mobius &first) const; // this o first
  Mobius inverse() const { return {d, -b, -c, a}; }
  // The transformation that takes z1, z2, z3 to w1, w2, w3 (finite, distinct).
  static Mobius through(const Complex (&z)[3], const Complex (&w)[3]);
};

} // namespace meromorph
