#include "match/flat_torus.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "maps/genus1_map.h"

namespace meromorph {

using Complex = std::complex<double>;

std::array<Complex, 2> reduced_lattice_basis(Complex tau) {
  Complex w1(1, 0), w2 = tau;
  for (int step = 0; step < 200; ++step) {
    w2 -= std::round((w2 / w1).real()) * w1;
    if (std::abs(w2) >= std::abs(w1) * (1 - 1e-14)) break;
    const Complex shorter = w2;
    w2 = -w1, w1 = shorter; // tau -> -1 / tau: the orientation kept
  }
  return {w1, w2};
}

Eigen::Vector2d FlatTorus::coordinates(Complex z) const {
  const double v = z.imag() / tau.imag();
  return {z.real() - v * tau.real(), v};
}

double FlatTorus::distance(const Eigen::Vector2d &a, const Eigen::Vector2d &b) const {
  Eigen::Vector2d d = a - b;
  d -= d.array().round().matrix();
  double shortest = std::numeric_limits<double>::infinity();
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      shortest = std::min(shortest, std::abs(point(d + Eigen::Vector2d(i, j))));
  return shortest;
}

FlatTorus flat_torus(const Mesh &mesh, const MeshEdges &edges, const Eigen::VectorXcd &psi,
                     Complex period_b) {
  const int vertex_count = int(mesh.vert.size());
  const auto [w1, w2] = reduced_lattice_basis(period_b);
  FlatTorus torus;
  torus.tau = w2 / w1;
  // In the reduced basis the shortest period is 1: the form divided by w1.
  const Eigen::VectorXcd form = psi / w1;
  const std::vector<Complex> z =
      integrated_form(0, edges_at_vertices(edges, vertex_count), edges, form);
  for (const Complex &value : z) {
    Eigen::Vector2d uv = torus.coordinates(value);
    torus.vertex.push_back(uv - uv.array().floor().matrix());
  }
  torus.faces.resize(mesh.face.size());
  torus.face_areas.resize(mesh.face.size());
  for (size_t f = 0; f < mesh.face.size(); ++f) {
    const int first = int(index_of(mesh, mesh.face[f].cV(0)));
    Complex corner[3];
    corner[0] = torus.point(torus.vertex[size_t(first)]);
    for (int k = 0; k < 2; ++k)
      corner[k + 1] =
          corner[k] + double(edges.face_signs[f][size_t(k)]) * form[edges.face_edges[f][size_t(k)]];
    for (int k = 0; k < 3; ++k)
      torus.faces[f][size_t(k)] = torus.coordinates(corner[k]);
    torus.face_areas[f] =
        0.5 * std::imag(std::conj(corner[1] - corner[0]) * (corner[2] - corner[0]));
  }
  return torus;
}

std::uint64_t FlatTorusLocator::key(int level, std::int64_t i, std::int64_t j) {
  const std::int64_t cells = std::int64_t(1) << level;
  const std::uint64_t wrapped_i = std::uint64_t(((i % cells) + cells) % cells);
  const std::uint64_t wrapped_j = std::uint64_t(((j % cells) + cells) % cells);
  return (std::uint64_t(level) << 58) | (wrapped_i << 29) | wrapped_j;
}

FlatTorusLocator::FlatTorusLocator(const FlatTorus &torus) : torus_(torus) {
  for (size_t f = 0; f < torus.faces.size(); ++f) {
    const auto &corners = torus.faces[f];
    if (!(corners[0].allFinite() && corners[1].allFinite() && corners[2].allFinite())) continue;
    const Eigen::Vector2d low = corners[0].cwiseMin(corners[1]).cwiseMin(corners[2]);
    const Eigen::Vector2d high = corners[0].cwiseMax(corners[1]).cwiseMax(corners[2]);
    const double extent = std::max((high - low).maxCoeff(), 1e-300);
    // The finest level whose cells are at least as large as the face: it spans 2 x 2 at most.
    const int level = std::clamp(int(std::floor(-std::log2(extent))), 0, max_level);
    const double cells = std::ldexp(1.0, level);
    used_[size_t(level)] = true;
    std::vector<std::uint64_t> keys;
    for (auto i = std::int64_t(std::floor(low[0] * cells));
         i <= std::int64_t(std::floor(high[0] * cells)); ++i)
      for (auto j = std::int64_t(std::floor(low[1] * cells));
           j <= std::int64_t(std::floor(high[1] * cells)); ++j)
        keys.push_back(key(level, i, j));
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    for (std::uint64_t k : keys)
      cells_[k].push_back(int(f));
  }
}

FlatTorusLocator::Hold FlatTorusLocator::holding(const Eigen::Vector2d &point) const {
  Hold best;
  double best_margin = -std::numeric_limits<double>::infinity();
  if (!point.allFinite()) return best;
  const Eigen::Vector2d p = point - point.array().floor().matrix();
  for (int level = 0; level <= max_level; ++level) {
    if (!used_[size_t(level)]) continue;
    const double cells = std::ldexp(1.0, level);
    const auto found = cells_.find(
        key(level, std::int64_t(std::floor(p[0] * cells)), std::int64_t(std::floor(p[1] * cells))));
    if (found == cells_.end()) continue;
    for (int f : found->second) {
      const auto &c = torus_.faces[size_t(f)];
      const Eigen::Vector2d e1 = c[1] - c[0], e2 = c[2] - c[0];
      const double det = e1[0] * e2[1] - e1[1] * e2[0];
      if (!(std::abs(det) > 0)) continue;
      // The representative of p nearest the face (its corners are within one period of [0,1)^2).
      for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j) {
          const Eigen::Vector2d d = p + Eigen::Vector2d(i, j) - c[0];
          const double b1 = (d[0] * e2[1] - d[1] * e2[0]) / det;
          const double b2 = (e1[0] * d[1] - e1[1] * d[0]) / det;
          const Eigen::Vector3d weights(1 - b1 - b2, b1, b2);
          const double margin = weights.minCoeff();
          if (margin > best_margin) best_margin = margin, best = {f, weights};
        }
      if (best_margin >= 0) return best;
    }
  }
  return best;
}

} // namespace meromorph
