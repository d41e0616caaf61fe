#include "match/torus_alignment.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/errors.h"
#include "common/parallel_for.h"

namespace meromorph {
namespace {

using Complex = std::complex<double>;
constexpr int grid_size = 64; // samples per period, both ways

// A function of the torus sampled at the centres of a grid_size x grid_size grid of lattice
// coordinates, clipped to [low, high], read back with bilinear interpolation.
struct TorusRaster {
  std::vector<double> values; // [i * grid_size + j] at ((i + 1/2) / n, (j + 1/2) / n)

  TorusRaster(const TorusFunction &f, double low, double high) : values(grid_size * grid_size) {
    parallel_for(values.size(), [&](size_t k) {
      const Eigen::Vector2d p((double(k / grid_size) + 0.5) / grid_size,
                              (double(k % grid_size) + 0.5) / grid_size);
      const FlatTorusLocator::Hold hold = f.locator.holding(p);
      double value = 0;
      if (hold.face >= 0)
        for (int c = 0; c < 3; ++c)
          value += hold.weights[c] * f.values[size_t(f.triangles[size_t(hold.face)][size_t(c)])];
      values[k] = std::clamp(value, low, high);
    });
  }
  double at(int i, int j) const {
    i = ((i % grid_size) + grid_size) % grid_size, j = ((j % grid_size) + grid_size) % grid_size;
    return values[size_t(i * grid_size + j)];
  }
  double interpolated(const Eigen::Vector2d &p) const {
    const double x = p[0] * grid_size - 0.5, y = p[1] * grid_size - 0.5;
    const double fx = std::floor(x), fy = std::floor(y), s = x - fx, t = y - fy;
    const int i = int(fx), j = int(fy);
    return (1 - s) * ((1 - t) * at(i, j) + t * at(i, j + 1)) +
           s * ((1 - t) * at(i + 1, j) + t * at(i + 1, j + 1));
  }
};

Eigen::Vector2d grid_point(int i, int j) {
  return {(i + 0.5) / grid_size, (j + 0.5) / grid_size};
}

// Mean squared difference between the source's samples and the target at M x + c.
double mismatch(const TorusRaster &source, const TorusRaster &target, const Eigen::Matrix2i &map,
                const Eigen::Vector2d &shift) {
  const Eigen::Matrix2d m = map.cast<double>();
  double sum = 0;
  for (int i = 0; i < grid_size; ++i)
    for (int j = 0; j < grid_size; ++j) {
      const double d = source.at(i, j) - target.interpolated(m * grid_point(i, j) + shift);
      sum += d * d;
    }
  return sum / (grid_size * grid_size);
}

// Every translation by whole grid cells: the cost of each (a circular correlation; the grid's
// points go to grid points since M is an integer matrix).
std::vector<double> shift_costs(const TorusRaster &source, const TorusRaster &target,
                                const Eigen::Matrix2i &map) {
  std::vector<double> costs(grid_size * grid_size);
  parallel_for(costs.size(), [&](size_t k) {
    const int a = int(k / grid_size), b = int(k % grid_size);
    double sum = 0;
    for (int i = 0; i < grid_size; ++i)
      for (int j = 0; j < grid_size; ++j) {
        const double d = source.at(i, j) - target.at(map(0, 0) * i + map(0, 1) * j + a,
                                                     map(1, 0) * i + map(1, 1) * j + b);
        sum += d * d;
      }
    costs[k] = sum / (grid_size * grid_size);
  });
  return costs;
}

// The translation c for which M (grid point (i, j)) + c is grid point (M (i, j) + (a, b)).
Eigen::Vector2d shift_of_cells(const Eigen::Matrix2i &map, int a, int b) {
  const Eigen::Vector2d half(0.5, 0.5);
  return (Eigen::Vector2d(a, b) + half - map.cast<double>() * half) / grid_size;
}

// Local search on c: steps along the two axes, halved when none helps.
Eigen::Vector2d refined(const TorusRaster &source, const TorusRaster &target,
                        const Eigen::Matrix2i &map, Eigen::Vector2d shift, double &cost) {
  cost = mismatch(source, target, map, shift);
  for (double step = 1.0 / grid_size; step > 1e-4 / grid_size;) {
    bool moved = false;
    for (const Eigen::Vector2d &direction : {Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 0),
                                             Eigen::Vector2d(0, 1), Eigen::Vector2d(0, -1)}) {
      const Eigen::Vector2d trial = shift + step * direction;
      const double c = mismatch(source, target, map, trial);
      if (c < cost) cost = c, shift = trial, moved = true;
    }
    if (!moved) step /= 2;
  }
  return shift;
}

std::vector<Eigen::Matrix2i> candidate_maps(Complex tau_source, Complex tau_target) {
  std::vector<std::pair<double, Eigen::Matrix2i>> all;
  for (int a = -3; a <= 3; ++a)
    for (int b = -3; b <= 3; ++b)
      for (int c = -3; c <= 3; ++c)
        for (int d = -3; d <= 3; ++d) {
          if (a * d - b * c != 1) continue;
          Eigen::Matrix2i m;
          m << a, b, c, d;
          all.emplace_back(lattice_map_dilatation(m, tau_source, tau_target), m);
        }
  double least = std::numeric_limits<double>::infinity();
  for (const auto &[k, m] : all)
    least = std::min(least, k);
  std::vector<Eigen::Matrix2i> out;
  for (const auto &[k, m] : all)
    if (k <= 1.25 * least) out.push_back(m);
  return out;
}

} // namespace

double lattice_map_dilatation(const Eigen::Matrix2i &map, Complex tau_source, Complex tau_target) {
  // z -> a z + b conj(z) taking 1 and tau_source to the images of (1, 0) and (0, 1).
  const Complex one = double(map(0, 0)) + double(map(1, 0)) * tau_target;
  const Complex tau = double(map(0, 1)) + double(map(1, 1)) * tau_target;
  const Complex b = (tau - tau_source * one) / (std::conj(tau_source) - tau_source);
  const Complex a = one - b;
  const double difference = std::abs(a) - std::abs(b);
  return difference > 0 ? (std::abs(a) + std::abs(b)) / difference
                        : std::numeric_limits<double>::infinity();
}

Eigen::Vector2d TorusAlignment::apply(const Eigen::Vector2d &x) const {
  return lattice_map.cast<double>() * x + shift;
}

Eigen::Vector2d TorusAlignment::apply_inverse(const Eigen::Vector2d &y) const {
  Eigen::Matrix2d inverse;
  inverse << lattice_map(1, 1), -lattice_map(0, 1), -lattice_map(1, 0), lattice_map(0, 0);
  return inverse * (y - shift);
}

TorusAlignment align_tori(const TorusFunction &source, const TorusFunction &target,
                          const std::vector<std::pair<int, int>> &landmarks) {
  const std::vector<Eigen::Matrix2i> maps = candidate_maps(source.torus.tau, target.torus.tau);
  // One range for both functions: the source's values from the 2nd to the 98th percentile.
  std::vector<double> sorted = source.values;
  std::sort(sorted.begin(), sorted.end());
  const double low = sorted.empty() ? 0 : sorted[sorted.size() / 50],
               high = sorted.empty() ? 0 : sorted[sorted.size() - 1 - sorted.size() / 50];
  const TorusRaster source_raster(source, low, high), target_raster(target, low, high);

  TorusAlignment best;
  best.cost = std::numeric_limits<double>::infinity();
  if (!landmarks.empty()) {
    double best_residual = std::numeric_limits<double>::infinity();
    for (const Eigen::Matrix2i &map : maps) {
      TorusAlignment trial;
      trial.lattice_map = map;
      // c: the landmarks' differences, each taken nearest the first's, averaged.
      std::vector<Eigen::Vector2d> differences;
      for (const auto &[i, j] : landmarks)
        differences.push_back(target.torus.vertex[size_t(j)] -
                              map.cast<double>() * source.torus.vertex[size_t(i)]);
      for (Eigen::Vector2d &d : differences) {
        d -= (d - differences.front()).array().round().matrix();
        trial.shift += d / double(differences.size());
      }
      for (const auto &[i, j] : landmarks)
        trial.landmark_distance_max =
            std::max(trial.landmark_distance_max,
                     target.torus.distance(trial.apply(source.torus.vertex[size_t(i)]),
                                           target.torus.vertex[size_t(j)]));
      trial.cost = mismatch(source_raster, target_raster, map, trial.shift);
      const double residual = trial.landmark_distance_max;
      if (residual < best_residual - 1e-6 ||
          (residual < best_residual + 1e-6 && trial.cost < best.cost))
        best = trial, best_residual = std::min(best_residual, residual);
    }
    best.method = landmarks.size() == 1
                      ? std::string("landmarks: the lattice map through the pair that best "
                                    "matches the log conformal factors")
                      : "landmarks: the lattice map and translation nearest all " +
                            std::to_string(landmarks.size()) + " pairs";
  } else {
    double typical_cost = 0;
    struct Minimum {
      Eigen::Matrix2i map;
      Eigen::Vector2d shift;
      double cost;
    };
    std::vector<Minimum> minima;
    for (const Eigen::Matrix2i &map : maps) {
      const std::vector<double> costs = shift_costs(source_raster, target_raster, map);
      std::vector<double> ordered = costs;
      std::nth_element(ordered.begin(), ordered.begin() + long(ordered.size() / 2), ordered.end());
      typical_cost = std::max(typical_cost, ordered[ordered.size() / 2]);
      // The local minima of the costs over the (periodic) grid of translations.
      for (int a = 0; a < grid_size; ++a)
        for (int b = 0; b < grid_size; ++b) {
          const double c = costs[size_t(a * grid_size + b)];
          bool lowest = true;
          for (int i = -1; i <= 1 && lowest; ++i)
            for (int j = -1; j <= 1 && lowest; ++j) {
              const int x = (a + i + grid_size) % grid_size, y = (b + j + grid_size) % grid_size;
              lowest =
                  (i == 0 && j == 0) || c < costs[size_t(x * grid_size + y)] ||
                  (c == costs[size_t(x * grid_size + y)] && x * grid_size + y > a * grid_size + b);
            }
          if (lowest) minima.push_back({map, shift_of_cells(map, a, b), c});
        }
    }
    std::sort(minima.begin(), minima.end(),
              [](const Minimum &x, const Minimum &y) { return x.cost < y.cost; });
    if (minima.size() > 8) minima.resize(8);
    parallel_for(minima.size(), [&](size_t k) {
      minima[k].shift =
          refined(source_raster, target_raster, minima[k].map, minima[k].shift, minima[k].cost);
    });
    std::sort(minima.begin(), minima.end(),
              [](const Minimum &x, const Minimum &y) { return x.cost < y.cost; });
    best.lattice_map = minima.front().map;
    best.shift = minima.front().shift;
    best.cost = minima.front().cost;
    best.method = "automatic: the lattice map and translation that best match the log conformal "
                  "factors";
    for (size_t k = 1; k < minima.size(); ++k) {
      const bool same = minima[k].map == best.lattice_map &&
                        target.torus.distance(minima[k].shift, best.shift) < 2.0 / grid_size;
      // Within a fifth of the way to a random translation's cost, and within three times the
      // best's (its mismatch is the two triangulations' own: an alternative that costs many
      // times that is a worse fit, not a symmetry).
      if (!same && minima[k].cost <= best.cost + 0.2 * (typical_cost - best.cost) &&
          minima[k].cost <= 3 * best.cost)
        best.alternatives.push_back({minima[k].map, minima[k].shift, minima[k].cost});
    }
  }
  best.dilatation = lattice_map_dilatation(best.lattice_map, source.torus.tau, target.torus.tau);
  return best;
}

} // namespace meromorph
