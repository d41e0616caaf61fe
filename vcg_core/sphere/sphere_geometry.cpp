#include "sphere/sphere_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Geometry>

#include "common/parallel_for.h"

namespace meromorph {

Eigen::Vector3d to_sphere(const Complex &w) {
  if (!std::isfinite(w.real()) || !std::isfinite(w.imag())) return {0, 0, 1};
  const double r2 = std::norm(w);
  if (r2 > 1e300) return {0, 0, 1};
  return Eigen::Vector3d(2 * w.real(), -2 * w.imag(), r2 - 1) / (r2 + 1);
}

Eigen::Vector3d to_sphere(const PlaneValue &value) {
  return value.infinite ? Eigen::Vector3d(0, 0, 1) : to_sphere(value.w);
}

std::vector<Eigen::Vector3d> to_sphere(const std::vector<PlaneValue> &values) {
  std::vector<Eigen::Vector3d> points(values.size());
  parallel_for(values.size(), [&](size_t i) { points[i] = to_sphere(values[i]); });
  return points;
}

Complex to_plane(const Eigen::Vector3d &p) {
  const double denominator = std::max(1.0 - p.z(), 1e-300);
  return {p.x() / denominator, -p.y() / denominator};
}

namespace {

// Van Oosterom and Strackee (1983): the solid angle is 2 atan2(numerator, denominator). The
// triple product a . (b x c) equals a . ((b - a) x (c - a)); the differences keep it accurate
// relative to a tiny triangle's area (the plain form has an error of about 1e-16 whatever the
// triangle's size).
std::array<double, 2> solid_angle_parts(const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                                        const Eigen::Vector3d &c) {
  return {a.dot((b - a).cross(c - a)), 1.0 + a.dot(b) + b.dot(c) + c.dot(a)};
}

} // namespace

double signed_solid_angle(const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                          const Eigen::Vector3d &c) {
  const auto [numerator, denominator] = solid_angle_parts(a, b, c);
  return 2.0 * std::atan2(numerator, denominator);
}

bool solid_angle_clearly_above(const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                               const Eigen::Vector3d &c, double threshold) {
  // atan(x) >= (pi / 4) x on [0, 1], and atan2 >= pi / 4 beyond (or d <= 0): n > threshold d
  // leaves a margin of pi / 2 over the threshold, far more than the rounding of either side.
  const auto [numerator, denominator] = solid_angle_parts(a, b, c);
  return numerator > 0 && (denominator <= 0 || numerator > threshold * denominator);
}

Complex chart_at(const Eigen::Vector3d &p, const Eigen::Vector3d &q) {
  // Rotate p to the south pole (0, 0, -1), where the plane coordinate is 0.
  const Eigen::Quaterniond rotation =
      Eigen::Quaterniond::FromTwoVectors(p, Eigen::Vector3d(0, 0, -1));
  return to_plane(rotation * q);
}

double swept_angle(const Eigen::Vector3d &center, const Eigen::Vector3d &a,
                   const Eigen::Vector3d &b) {
  // The chart at `center` is conformal and takes the great circles through it to the lines
  // through 0: the angle from a to b there is the angle between their directions in the tangent
  // plane at `center` (a - center with its normal part taken off: accurate for a beside center).
  const Eigen::Vector3d da = a - center, db = b - center;
  const Eigen::Vector3d ta = da - da.dot(center) * center, tb = db - db.dot(center) * center;
  if (ta.squaredNorm() == 0 || tb.squaredNorm() == 0) return 0.0;
  const double angle = std::atan2(center.dot(ta.cross(tb)), ta.dot(tb));
  return angle < -M_PI + 0.05 ? angle + 2 * M_PI : angle;
}

bool folded_image(const Eigen::Vector3d &a, const Eigen::Vector3d &b, const Eigen::Vector3d &c) {
  // A positive numerator puts the angle in (0, 2 pi): not folded, no arctangent needed.
  if (solid_angle_clearly_above(a, b, c, 0.0)) return false;
  const double chord =
      std::max({(a - b).squaredNorm(), (b - c).squaredNorm(), (c - a).squaredNorm()});
  return signed_solid_angle(a, b, c) < -1e-9 * chord;
}

bool chord_turned_over(const Eigen::Vector3d &a, const Eigen::Vector3d &b, const Eigen::Vector3d &c,
                       double margin) {
  const double chord =
      std::max({(a - b).squaredNorm(), (b - c).squaredNorm(), (c - a).squaredNorm()});
  return !(a.dot((b - a).cross(c - a)) > margin * chord);
}

bool collapsed_image(const Eigen::Vector3d &a, const Eigen::Vector3d &b, const Eigen::Vector3d &c) {
  return std::max({(a - b).norm(), (b - c).norm(), (c - a).norm()}) < 1e-14;
}

Eigen::Vector3d from_chart(const Eigen::Vector3d &p, const Complex &w) {
  const Eigen::Quaterniond rotation =
      Eigen::Quaterniond::FromTwoVectors(p, Eigen::Vector3d(0, 0, -1));
  return rotation.inverse() * to_sphere(w);
}

PlaneValue to_plane_value(const Eigen::Vector3d &p) {
  if (p.z() >= 1.0 || std::hypot(p.x(), p.y()) < 1e-300) {
    if (p.z() > 0) return {Complex(), true};
  }
  return {to_plane(p), false};
}

PlaneValue Mobius::apply(const PlaneValue &value) const {
  if (value.infinite) {
    if (std::abs(c) == 0) return {Complex(), true};
    return {a / c, false};
  }
  const Complex denominator = c * value.w + d;
  if (std::abs(denominator) == 0) return {Complex(), true};
  return {(a * value.w + b) / denominator, false};
}

Mobius Mobius::after(const Mobius &first) const {
  Mobius m{a * first.a + b * first.c, a * first.b + b * first.d, c * first.a + d * first.c,
           c * first.b + d * first.d};
  const Complex scale = std::sqrt(m.a * m.d - m.b * m.c);
  m.a /= scale;
  m.b /= scale;
  m.c /= scale;
  m.d /= scale;
  return m;
}

Mobius Mobius::through(const Complex (&z)[3], const Complex (&w)[3]) {
  // M1 takes z1, z2, z3 to 0, 1, infinity; M2 the same for w; the answer is M2^-1 o M1.
  const Mobius m1{z[1] - z[2], -z[0] * (z[1] - z[2]), z[1] - z[0], -z[2] * (z[1] - z[0])};
  const Mobius m2{w[1] - w[2], -w[0] * (w[1] - w[2]), w[1] - w[0], -w[2] * (w[1] - w[0])};
  const Mobius m2_inverse{m2.d, -m2.b, -m2.c, m2.a};
  return m2_inverse.after(m1);
}

} // namespace meromorph
