#include "match/sphere_alignment.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <Eigen/Geometry>

#include "common/errors.h"
#include "common/parallel_for.h"
#include "sphere/mobius_centering.h"
#include "sphere/sphere_triangle_grid.h"

namespace meromorph {
namespace {

constexpr double pi = 3.14159265358979323846;

// n points spread evenly over the unit sphere (a Fibonacci spiral).
std::vector<Eigen::Vector3d> spread_points(int n) {
  std::vector<Eigen::Vector3d> points;
  const double golden = pi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / n, r = std::sqrt(std::max(0.0, 1.0 - z * z));
    points.emplace_back(r * std::cos(golden * k), r * std::sin(golden * k), z);
  }
  return points;
}

Eigen::Matrix3d rotation_by(const Eigen::Vector3d &vector) {
  const double angle = vector.norm();
  if (angle < 1e-300) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, vector / angle).toRotationMatrix();
}

double rotation_angle(const Eigen::Matrix3d &a, const Eigen::Matrix3d &b) {
  const double cosine = ((a.transpose() * b).trace() - 1.0) / 2.0;
  return std::acos(std::clamp(cosine, -1.0, 1.0));
}

// A function of the sphere, interpolated from its vertices on a triangulation.
double value_at(const SphereTriangleGrid &grid, const SphereFunction &f, const Eigen::Vector3d &p,
                bool &held) {
  const SphereTriangleGrid::Hold hold = grid.holding_with_weights(p);
  held = hold.triangle >= 0;
  if (!held) return 0;
  const auto &t = f.triangles[size_t(hold.triangle)];
  return hold.weights[0] * f.values[size_t(t[0])] + hold.weights[1] * f.values[size_t(t[1])] +
         hold.weights[2] * f.values[size_t(t[2])];
}

// The target's function on a latitude-longitude raster, read back with bilinear interpolation.
class Raster {
public:
  Raster(const SphereTriangleGrid &grid, const SphereFunction &f, int rows)
      : rows_(rows), columns_(2 * rows), values_(size_t(rows_) * size_t(columns_), 0.0) {
    parallel_for(size_t(rows_), [&](size_t i) {
      const double theta = pi * (double(i) + 0.5) / rows_;
      for (int j = 0; j < columns_; ++j) {
        const double phi = 2 * pi * (double(j) + 0.5) / columns_;
        bool held = false;
        const double value = value_at(
            grid, f,
            {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)},
            held);
        values_[i * size_t(columns_) + size_t(j)] = value;
      }
    });
  }
  double at(const Eigen::Vector3d &p) const {
    const double theta = std::acos(std::clamp(p.z(), -1.0, 1.0));
    double phi = std::atan2(p.y(), p.x());
    if (phi < 0) phi += 2 * pi;
    const double u = theta / pi * rows_ - 0.5, v = phi / (2 * pi) * columns_ - 0.5;
    const int i0 = std::clamp(int(std::floor(u)), 0, rows_ - 1), i1 = std::min(i0 + 1, rows_ - 1);
    const double s = std::clamp(u - i0, 0.0, 1.0);
    const int j0 = int(std::floor(v));
    const double t = v - j0;
    const auto cell = [&](int i, int j) {
      return values_[size_t(i) * size_t(columns_) + size_t(((j % columns_) + columns_) % columns_)];
    };
    return (1 - s) * ((1 - t) * cell(i0, j0) + t * cell(i0, j0 + 1)) +
           s * ((1 - t) * cell(i1, j0) + t * cell(i1, j0 + 1));
  }

private:
  int rows_, columns_;
  std::vector<double> values_;
};

struct Samples {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> values;
};

Samples source_samples(const SphereTriangleGrid &grid, const SphereFunction &f, int n, double low,
                       double high) {
  Samples out;
  for (const Eigen::Vector3d &p : spread_points(n)) {
    bool held = false;
    const double value = value_at(grid, f, p, held);
    if (!held) continue;
    out.points.push_back(p);
    out.values.push_back(std::clamp(value, low, high));
  }
  return out;
}

double mismatch(const Samples &samples, const Raster &target, const Eigen::Matrix3d &rotation,
                double low, double high) {
  double sum = 0;
  for (size_t k = 0; k < samples.points.size(); ++k) {
    const double d =
        samples.values[k] - std::clamp(target.at(rotation * samples.points[k]), low, high);
    sum += d * d;
  }
  return samples.points.empty() ? 0 : sum / double(samples.points.size());
}

// Local search: small rotations about the three axes, the step halved from 8 degrees when none
// helps, down to 0.001 degrees.
Eigen::Matrix3d refined(const Samples &samples, const Raster &target, Eigen::Matrix3d rotation,
                        double low, double high, double &cost) {
  cost = mismatch(samples, target, rotation, low, high);
  for (double step = 8.0 * pi / 180; step > 0.001 * pi / 180;) {
    bool better = false;
    for (int axis = 0; axis < 3 && !better; ++axis)
      for (double sign : {1.0, -1.0}) {
        Eigen::Vector3d turn = Eigen::Vector3d::Zero();
        turn[axis] = sign * step;
        const Eigen::Matrix3d candidate = rotation_by(turn) * rotation;
        const double c = mismatch(samples, target, candidate, low, high);
        if (c < cost) {
          cost = c, rotation = candidate, better = true;
          break;
        }
      }
    if (!better) step /= 2;
  }
  return rotation;
}

// Nelder-Mead on a few parameters.
template <class Cost> Eigen::VectorXd minimized(Cost &&cost, Eigen::VectorXd start, double size) {
  const int n = int(start.size());
  std::vector<Eigen::VectorXd> simplex(size_t(n + 1), start);
  for (int k = 0; k < n; ++k)
    simplex[size_t(k + 1)][k] += size;
  std::vector<double> values;
  for (const auto &x : simplex)
    values.push_back(cost(x));
  for (int iteration = 0; iteration < 2000; ++iteration) {
    std::vector<size_t> order(simplex.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return values[a] < values[b]; });
    const size_t best = order.front(), worst = order.back(), second = order[order.size() - 2];
    if (values[worst] - values[best] < 1e-16 * (1 + std::abs(values[best]))) break;
    Eigen::VectorXd centre = Eigen::VectorXd::Zero(n);
    for (size_t k : order)
      if (k != worst) centre += simplex[k] / n;
    const Eigen::VectorXd reflected = centre + (centre - simplex[worst]);
    const double fr = cost(reflected);
    if (fr < values[best]) {
      const Eigen::VectorXd expanded = centre + 2 * (centre - simplex[worst]);
      const double fe = cost(expanded);
      simplex[worst] = fe < fr ? expanded : reflected;
      values[worst] = std::min(fe, fr);
    } else if (fr < values[second]) {
      simplex[worst] = reflected, values[worst] = fr;
    } else {
      const Eigen::VectorXd contracted = centre + 0.5 * (simplex[worst] - centre);
      const double fc = cost(contracted);
      if (fc < values[worst]) {
        simplex[worst] = contracted, values[worst] = fc;
      } else {
        for (size_t k : order)
          if (k != best) {
            simplex[k] = simplex[best] + 0.5 * (simplex[k] - simplex[best]);
            values[k] = cost(simplex[k]);
          }
      }
    }
  }
  return simplex[size_t(std::min_element(values.begin(), values.end()) - values.begin())];
}

} // namespace

Eigen::Vector3d SphereAlignment::apply(const Eigen::Vector3d &x) const {
  const Eigen::Vector3d moved = to_sphere(plane.apply(to_plane_value(x)));
  return rotation * (ball.squaredNorm() > 0 ? ball_translate(moved, ball) : moved);
}

Eigen::Vector3d SphereAlignment::apply_inverse(const Eigen::Vector3d &y) const {
  Eigen::Vector3d x = rotation.transpose() * y;
  if (ball.squaredNorm() > 0) x = ball_translate(x, -ball);
  return to_sphere(plane.inverse().apply(to_plane_value(x)));
}

std::vector<double> log_conformal_factor(const std::vector<Eigen::Vector3d> &positions,
                                         const std::vector<std::array<int, 3>> &triangles,
                                         const std::vector<double> &image_areas) {
  std::vector<double> surface(positions.size(), 0.0), image(positions.size(), 0.0);
  double surface_total = 0, image_total = 0;
  for (size_t f = 0; f < triangles.size(); ++f) {
    const auto &t = triangles[f];
    const double a = 0.5 * (positions[size_t(t[1])] - positions[size_t(t[0])])
                               .cross(positions[size_t(t[2])] - positions[size_t(t[0])])
                               .norm();
    const double b = std::abs(image_areas[f]);
    for (int k = 0; k < 3; ++k) {
      surface[size_t(t[k])] += a / 3;
      image[size_t(t[k])] += b / 3;
    }
    surface_total += a, image_total += b;
  }
  std::vector<double> out(positions.size(), 0.0);
  for (size_t v = 0; v < out.size(); ++v)
    out[v] = std::log(std::max(surface[v] / surface_total, 1e-300) /
                      std::max(image[v] / image_total, 1e-300));
  return out;
}

SphereAlignment align_by_landmarks(const std::vector<Eigen::Vector3d> &source_sphere,
                                   const std::vector<Eigen::Vector3d> &target_sphere,
                                   const std::vector<std::pair<int, int>> &landmarks) {
  if (landmarks.size() < 3)
    throw InputError("a genus-0 match needs three landmark pairs or more to fix the Moebius "
                     "transformation (" +
                     std::to_string(landmarks.size()) +
                     " given), or none "
                     "for the automatic alignment");
  std::vector<Eigen::Vector3d> a, b;
  for (const auto &[i, j] : landmarks) {
    a.push_back(source_sphere[size_t(i)]);
    b.push_back(target_sphere[size_t(j)]);
  }
  // The three most spread out (largest chord triangle on both sides), among the first 64.
  const size_t n = std::min<size_t>(a.size(), 64);
  std::array<size_t, 3> best{0, 1, 2};
  double spread = -1;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j)
      for (size_t k = j + 1; k < n; ++k) {
        const double s = std::min((a[j] - a[i]).cross(a[k] - a[i]).norm(),
                                  (b[j] - b[i]).cross(b[k] - b[i]).norm());
        if (s > spread) spread = s, best = {i, j, k};
      }
  if (spread < 1e-12)
    throw InputError("the landmarks fall on one point or one circle of the sphere: give three that "
                     "are far apart on each surface");
  SphereAlignment alignment;
  // Both triples rotated so that no point is at the north pole, where the plane has no finite
  // coordinate; the rotation is put back after.
  const Eigen::Vector3d away = (a[best[0]] + a[best[1]] + a[best[2]]).normalized();
  const Eigen::Matrix3d turn_source =
      Eigen::Quaterniond::FromTwoVectors(away.allFinite() ? away : Eigen::Vector3d::UnitX(),
                                         -Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  const Eigen::Vector3d target_away = (b[best[0]] + b[best[1]] + b[best[2]]).normalized();
  const Eigen::Matrix3d turn_target =
      Eigen::Quaterniond::FromTwoVectors(target_away.allFinite() ? target_away
                                                                 : Eigen::Vector3d::UnitX(),
                                         -Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  Complex z[3], w[3];
  for (int k = 0; k < 3; ++k) {
    z[k] = to_plane(turn_source * a[best[size_t(k)]]);
    w[k] = to_plane(turn_target * b[best[size_t(k)]]);
  }
  // x -> turn_target^T M(turn_source x): the turn before M is folded into M through the plane.
  const Mobius through = Mobius::through(z, w);
  // Three points of the sphere fix the source's turn as a Moebius map of the plane.
  Complex p[3], q[3];
  const Eigen::Vector3d probes[3] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                     -Eigen::Vector3d::UnitX()};
  for (int k = 0; k < 3; ++k) {
    p[k] = to_plane(probes[k]);
    q[k] = to_plane(turn_source * probes[k]);
  }
  alignment.plane = through.after(Mobius::through(p, q));
  alignment.rotation = turn_target.transpose();
  alignment.method = "landmarks: the Moebius transformation through three pairs";
  if (a.size() > 3) {
    // Least squares over all pairs: a hyperbolic translation and a rotation after it.
    const SphereAlignment start = alignment;
    const auto cost = [&](const Eigen::VectorXd &x) {
      SphereAlignment trial = start;
      trial.ball = x.head<3>();
      if (trial.ball.norm() > 0.95) return 1e9;
      trial.rotation = rotation_by(x.tail<3>()) * start.rotation;
      double sum = 0;
      for (size_t k = 0; k < a.size(); ++k)
        sum += (trial.apply(a[k]) - b[k]).squaredNorm();
      return sum;
    };
    const Eigen::VectorXd x = minimized(cost, Eigen::VectorXd::Zero(6), 0.05);
    alignment.ball = x.head<3>();
    alignment.rotation = rotation_by(x.tail<3>()) * start.rotation;
    alignment.method = "landmarks: the Moebius transformation nearest all " +
                       std::to_string(a.size()) + " pairs (least squares)";
  }
  for (size_t k = 0; k < a.size(); ++k)
    alignment.landmark_distance_max =
        std::max(alignment.landmark_distance_max, (alignment.apply(a[k]) - b[k]).norm());
  return alignment;
}

std::vector<SphereAlignment> align_point_sets(const std::vector<Eigen::Vector3d> &a,
                                              const std::vector<Eigen::Vector3d> &b,
                                              double tolerance) {
  std::vector<SphereAlignment> out;
  if (a.size() != b.size() || a.size() < 3) return out;
  std::array<size_t, 3> spread{0, 1, 2};
  double largest = -1;
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = i + 1; j < a.size(); ++j)
      for (size_t k = j + 1; k < a.size(); ++k) {
        const double s = (a[j] - a[i]).cross(a[k] - a[i]).norm();
        if (s > largest) largest = s, spread = {i, j, k};
      }
  for (size_t i = 0; i < b.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j)
      for (size_t k = 0; k < b.size(); ++k) {
        if (i == j || j == k || i == k) continue;
        if ((b[j] - b[i]).cross(b[k] - b[i]).norm() < 1e-12) continue;
        SphereAlignment alignment = align_by_landmarks(
            a, b, {{int(spread[0]), int(i)}, {int(spread[1]), int(j)}, {int(spread[2]), int(k)}});
        double worst = 0;
        for (const Eigen::Vector3d &p : a) {
          const Eigen::Vector3d q = alignment.apply(p);
          double nearest = std::numeric_limits<double>::infinity();
          for (const Eigen::Vector3d &r : b)
            nearest = std::min(nearest, (q - r).norm());
          worst = std::max(worst, nearest);
        }
        alignment.landmark_distance_max = worst;
        if (worst <= tolerance) out.push_back(alignment);
      }
  std::sort(out.begin(), out.end(), [](const SphereAlignment &x, const SphereAlignment &y) {
    return x.landmark_distance_max < y.landmark_distance_max;
  });
  return out;
}

SphereAlignment align_by_functions(const SphereFunction &source, const SphereFunction &target) {
  const SphereTriangleGrid &source_grid = source.grid, &target_grid = target.grid;
  // One range for both functions: the source's values from the 2nd to the 98th percentile (the
  // tips of long parts, where the factor runs off exponentially, count as much as their edge).
  std::vector<double> sorted = source.values;
  std::sort(sorted.begin(), sorted.end());
  const double low = sorted.empty() ? 0 : sorted[sorted.size() / 50],
               high = sorted.empty() ? 0 : sorted[sorted.size() - 1 - sorted.size() / 50];
  const Raster raster(target_grid, target, 128);
  const Samples coarse = source_samples(source_grid, source, 300, low, high);
  const Samples fine = source_samples(source_grid, source, 2000, low, high);

  // Coarse: rotations about 200 axes by 0 to 180 degrees in steps of 15.
  struct Candidate {
    Eigen::Matrix3d rotation;
    double cost;
  };
  std::vector<Candidate> candidates{{Eigen::Matrix3d::Identity(), 0}};
  for (const Eigen::Vector3d &axis : spread_points(200))
    for (int step = 1; step <= 12; ++step)
      candidates.push_back({rotation_by(axis * (step * pi / 12)), 0});
  parallel_for(candidates.size(), [&](size_t k) {
    candidates[k].cost = mismatch(coarse, raster, candidates[k].rotation, low, high);
  });
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate &x, const Candidate &y) { return x.cost < y.cost; });
  // What a rotation picked at random costs: the scale against which "almost as well" is judged.
  const double typical_cost = candidates[candidates.size() / 2].cost;
  // The best eight that are 40 degrees apart (a symmetric surface's other fits among them), each
  // refined.
  std::vector<Candidate> starts;
  for (const Candidate &c : candidates) {
    if (starts.size() == 8) break;
    if (std::all_of(starts.begin(), starts.end(), [&](const Candidate &s) {
          return rotation_angle(s.rotation, c.rotation) > 40 * pi / 180;
        }))
      starts.push_back(c);
  }
  parallel_for(starts.size(), [&](size_t k) {
    starts[k].rotation = refined(fine, raster, starts[k].rotation, low, high, starts[k].cost);
  });
  std::sort(starts.begin(), starts.end(),
            [](const Candidate &x, const Candidate &y) { return x.cost < y.cost; });
  SphereAlignment alignment;
  alignment.rotation = starts.front().rotation;
  alignment.cost = starts.front().cost;
  alignment.method = "automatic: the rotation that best matches the log conformal factors";
  for (size_t k = 1; k < starts.size(); ++k) {
    const double angle = rotation_angle(starts[k].rotation, alignment.rotation);
    if (angle > 10 * pi / 180 &&
        starts[k].cost <= alignment.cost + 0.2 * (typical_cost - alignment.cost) &&
        std::none_of(alignment.alternatives.begin(), alignment.alternatives.end(),
                     [&](const SphereAlignment::Alternative &a) {
                       return std::abs(a.angle_from_best_degrees - angle * 180 / pi) < 1;
                     }))
      alignment.alternatives.push_back({angle * 180 / pi, starts[k].cost});
  }
  return alignment;
}

} // namespace meromorph
