#include "sphere/mobius_centering.h"

#include <algorithm>

#include <Eigen/Dense>

#include "common/parallel_for.h"

namespace meromorph {

Eigen::Vector3d ball_translate(const Eigen::Vector3d &x, const Eigen::Vector3d &c) {
  const Eigen::Vector3d d = x - c;
  const double d2 = d.squaredNorm();
  if (d2 < 1e-300) return -c.normalized(); // the point at c goes to the antipode of c's direction
  return ((1 - c.squaredNorm()) * d / d2 - c).normalized();
}

namespace {

constexpr size_t sample_size = 16384;
constexpr double sampled_beyond = 0.1; // centroid norm

Eigen::Vector3d translated_centroid(const std::vector<Eigen::Vector3d> &points,
                                    const std::vector<double> &weights, const Eigen::Vector3d &c) {
  // x, y, z and the weight, summed.
  const Eigen::Vector4d sum =
      chunked_sum(points.size(), Eigen::Vector4d::Zero().eval(), [&](size_t begin, size_t end) {
        Eigen::Vector4d part = Eigen::Vector4d::Zero();
        for (size_t i = begin; i < end; ++i) {
          part.head<3>() += weights[i] * ball_translate(points[i], c);
          part[3] += weights[i];
        }
        return part;
      });
  return sum.head<3>() / sum[3];
}

// The derivative of the translated centroid with respect to the translation, at 0.
Eigen::Matrix3d centroid_jacobian(const std::vector<Eigen::Vector3d> &points,
                                  const std::vector<double> &weights) {
  // The moment's six entries and the weight, summed.
  using Sums = Eigen::Matrix<double, 7, 1>;
  const Sums sum = chunked_sum(points.size(), Sums::Zero().eval(), [&](size_t begin, size_t end) {
    Sums part = Sums::Zero();
    for (size_t i = begin; i < end; ++i) {
      const Eigen::Vector3d &x = points[i];
      const double w = weights[i];
      part += w * (Sums() << x.x() * x.x(), x.y() * x.y(), x.z() * x.z(), x.x() * x.y(),
                   x.x() * x.z(), x.y() * x.z(), 1.0)
                      .finished();
    }
    return part;
  });
  Eigen::Matrix3d moment;
  moment << sum[0], sum[3], sum[4], sum[3], sum[1], sum[5], sum[4], sum[5], sum[2];
  return 2 * moment / sum[6] - 2 * Eigen::Matrix3d::Identity();
}

} // namespace

Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d> &points,
                         const std::vector<double> &weights) {
  return translated_centroid(points, weights, Eigen::Vector3d::Zero());
}

// The plane form of the ball translation by c: fitted through three points of the 26 cube
// directions whose points and images stay farthest from infinity (a strong translation pushes
// nearly everything towards one spot, which may be the north pole).
Mobius translation_matrix(const Eigen::Vector3d &c) {
  std::vector<std::pair<double, Eigen::Vector3d>> samples;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x || y || z) {
          const Eigen::Vector3d p = Eigen::Vector3d(x, y, z).normalized();
          samples.push_back({std::max(p.z(), ball_translate(p, c).z()), p});
        }
  std::sort(samples.begin(), samples.end(),
            [](const auto &a, const auto &b) { return a.first < b.first; });
  Complex from[3], to[3];
  int found = 0;
  for (const auto &[height, p] : samples) {
    if (height > 0.999) break;
    const Complex w = to_plane(p), image = to_plane(ball_translate(p, c));
    bool apart = true;
    for (int k = 0; k < found; ++k)
      apart &= std::abs(w - from[k]) > 1e-3 && std::abs(image - to[k]) > 1e-9;
    if (!apart) continue;
    from[found] = w;
    to[found] = image;
    if (++found == 3) break;
  }
  if (found < 3) return Mobius{};
  return Mobius::through(from, to);
}

MobiusCentering center_on_sphere(std::vector<PlaneValue> &values,
                                 const std::vector<double> &weights) {
  MobiusCentering out;
  const std::vector<PlaneValue> original = values;
  std::vector<Eigen::Vector3d> points = to_sphere(values);
  out.centroid_before = centroid(points, weights);
  Eigen::Vector3d current = out.centroid_before;
  for (; out.steps < 100 && current.norm() > 1e-12; ++out.steps) {
    // Far from centred, the step is chosen on an even sample of the points (their weights
    // kept): the choice needs the centroid to a percent, not to the last digit, and up to 24
    // candidates are weighed. The step taken is then measured on all points.
    const bool sampled = current.norm() > sampled_beyond && points.size() > 2 * sample_size;
    std::vector<Eigen::Vector3d> sample_points;
    std::vector<double> sample_weights;
    if (sampled) {
      const size_t stride = points.size() / sample_size;
      for (size_t i = 0; i < points.size(); i += stride) {
        sample_points.push_back(points[i]);
        sample_weights.push_back(weights[i]);
      }
    }
    const std::vector<Eigen::Vector3d> &judged = sampled ? sample_points : points;
    const std::vector<double> &judged_weights = sampled ? sample_weights : weights;
    // Newton step on c -> centroid after translating by c. At c = 0 the translation moves x by
    // -2 c + 2 (x . c) x to first order, so the Jacobian is 2 sum w x x^T / sum w - 2 I.
    Eigen::Vector3d newton = -centroid_jacobian(judged, judged_weights).fullPivLu().solve(current);
    if (!newton.allFinite()) newton = Eigen::Vector3d::Zero();
    if (newton.norm() > 0.95) newton *= 0.95 / newton.norm();
    // Far from centred (mass crowded at one spot), Newton's model is poor: also try pushing
    // straight away from the centroid by steps of several sizes, and keep the best.
    std::vector<Eigen::Vector3d> candidates;
    for (double scale = 1.0; scale > 1e-6; scale *= 0.5)
      candidates.push_back(scale * newton);
    for (double size : {0.99, 0.95, 0.9, 0.8, 0.6, 0.4, 0.2, 0.1})
      candidates.push_back(size * current.normalized());
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    double best = current.norm();
    for (const Eigen::Vector3d &candidate : candidates) {
      const double norm = translated_centroid(judged, judged_weights, candidate).norm();
      if (norm < best) {
        best = norm;
        c = candidate;
      }
      // Newton's own step, where it halves the distance, is taken at once: that is its region of
      // quadratic convergence (the others are for where its model is poor).
      if (&candidate == &candidates.front() && norm < 0.5 * current.norm()) break;
    }
    if (c.norm() == 0) break;
    out.transformation = translation_matrix(c).after(out.transformation);
    parallel_for(values.size(),
                 [&](size_t i) { values[i] = out.transformation.apply(original[i]); });
    points = to_sphere(values);
    const Eigen::Vector3d next = centroid(points, weights);
    if (next.norm() >= current.norm()) {
      current = next;
      break;
    }
    current = next;
  }
  out.centroid_after = current;
  return out;
}

} // namespace meromorph
