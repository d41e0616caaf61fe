#include "maps/star_kernel.h"

#include <Eigen/Dense>

namespace meromorph {

std::optional<std::pair<Eigen::Vector2d, double>>
star_kernel_centre(const std::vector<Eigen::Vector2d> &ring) {
  const size_t k = ring.size();
  if (k < 3) return std::nullopt;
  // Side j as n_j . p >= c_j: n_j its unit normal to the left of ring[j] -> ring[j + 1]. The
  // linear programme: maximise t with n_j . p - t >= c_j for every side; its optimum is where
  // three of them hold with equality.
  std::vector<Eigen::Vector2d> normal(k);
  std::vector<double> offset(k);
  for (size_t j = 0; j < k; ++j) {
    const Eigen::Vector2d side = ring[(j + 1) % k] - ring[j];
    const double length = side.norm();
    if (!(length > 0)) return std::nullopt;
    normal[j] = Eigen::Vector2d(-side.y(), side.x()) / length;
    offset[j] = normal[j].dot(ring[j]);
  }
  double scale = 0; // for the tolerance of "holds"
  for (const Eigen::Vector2d &q : ring)
    scale = std::max(scale, q.cwiseAbs().maxCoeff());
  const double tolerance = 1e-12 * std::max(scale, 1e-300);
  std::optional<std::pair<Eigen::Vector2d, double>> best;
  for (size_t a = 0; a < k; ++a)
    for (size_t b = a + 1; b < k; ++b)
      for (size_t c = b + 1; c < k; ++c) {
        Eigen::Matrix3d m;
        Eigen::Vector3d r;
        const size_t rows[3] = {a, b, c};
        for (int i = 0; i < 3; ++i) {
          m.row(i) << normal[rows[i]].x(), normal[rows[i]].y(), -1.0;
          r[i] = offset[rows[i]];
        }
        const Eigen::FullPivLU<Eigen::Matrix3d> lu(m);
        if (!lu.isInvertible()) continue;
        const Eigen::Vector3d x = lu.solve(r);
        const Eigen::Vector2d p = x.head<2>();
        const double t = x[2];
        if (!(t > 0) || (best && t <= best->second)) continue;
        bool inside = true;
        for (size_t j = 0; j < k && inside; ++j)
          inside = normal[j].dot(p) - offset[j] >= t - tolerance;
        if (inside) best = std::make_pair(p, t);
      }
  return best;
}

} // namespace meromorph
