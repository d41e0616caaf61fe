#include "remesh/flat_torus_lift.h"

#include <algorithm>
#include <cmath>

namespace meromorph {
namespace {

using Complex = std::complex<double>;

// The regular grid of the flat torus in units of w1 (the lattice is Z + tau Z): n x m points
// i a + j c, a = 1 / n, c = (tau + k) / m; both n and m even, so the half periods are grid points.
struct FlatGrid {
  int n = 2, m = 2;
  Complex tau, a, c;

  FlatGrid(Complex tau_, long long samples) : tau(tau_) {
    const double wanted = double(std::max<long long>(samples, 4));
    const double ideal_n = std::sqrt(wanted * std::sqrt(3.0) / (2.0 * tau.imag()));
    n = std::max(2, 2 * int(std::lround(ideal_n / 2)));
    m = std::max(2, 2 * int(std::lround(wanted / n / 2)));
    const int k = int(std::lround(m / (2.0 * n) - tau.real()));
    a = Complex(1.0 / n, 0);
    c = (tau + double(k)) / double(m);
  }

  // Grid coordinates (U, V) of z = U a + V c.
  Eigen::Vector2d coordinates(Complex z) const {
    const double v = z.imag() / c.imag();
    return {(z.real() - v * c.real()) * n, v};
  }
  int index(long long i, long long j) const {
    const long long wrapped_i = ((i % n) + n) % n, wrapped_j = ((j % m) + m) % m;
    return int(wrapped_j * n + wrapped_i);
  }
};

// d minus the lattice point (of Z + tau Z) nearest it.
Complex shortest(Complex d, Complex tau) {
  d -= std::round(d.imag() / tau.imag()) * tau;
  d -= std::round(d.real());
  Complex best = d;
  for (int s = -1; s <= 1; ++s)
    for (int t = -1; t <= 1; ++t) {
      const Complex other = d + double(s) + double(t) * tau;
      if (std::abs(other) < std::abs(best)) best = other;
    }
  return best;
}

struct Located {
  SurfacePoint point;
  double score = -1e300; // the smallest barycentric coordinate: the deeper inside, the better
};

// Every face's flat triangle, unwrapped from its first corner, holds the grid points inside it
// (`located`: per grid point, the face that holds it deepest); `face_at_vertex` gets a face of
// each vertex.
void locate_grid_points(const MappedSurface &surface, const std::vector<Complex> &flat, Complex w1,
                        const FlatGrid &grid, std::vector<Located> &located,
                        std::vector<int> &face_at_vertex) {
  face_at_vertex.assign(surface.positions.size(), -1);
  for (size_t f = 0; f < surface.faces.size(); ++f) {
    const auto &corners = surface.faces[f];
    std::array<Eigen::Vector2d, 3> at;
    const Complex start = flat[corners[0]] / w1;
    for (int k = 0; k < 3; ++k) {
      face_at_vertex[corners[k]] = int(f);
      at[k] = grid.coordinates(start + shortest(flat[corners[k]] / w1 - start, grid.tau));
    }
    const Eigen::Vector2d e1 = at[1] - at[0], e2 = at[2] - at[0];
    const double twice_area = e1.x() * e2.y() - e1.y() * e2.x();
    if (!(twice_area > 1e-14)) continue; // no flat area (or turned over): holds no grid point
    const Eigen::Vector2d low = at[0].cwiseMin(at[1]).cwiseMin(at[2]),
                          high = at[0].cwiseMax(at[1]).cwiseMax(at[2]);
    for (long long j = (long long)std::floor(low.y()); j <= (long long)std::ceil(high.y()); ++j)
      for (long long i = (long long)std::floor(low.x()); i <= (long long)std::ceil(high.x()); ++i) {
        const Eigen::Vector2d p = Eigen::Vector2d(double(i), double(j)) - at[0];
        const double w1_ = (p.x() * e2.y() - p.y() * e2.x()) / twice_area;
        const double w2_ = (e1.x() * p.y() - e1.y() * p.x()) / twice_area;
        const Eigen::Vector3d weights(1 - w1_ - w2_, w1_, w2_);
        const double score = weights.minCoeff();
        Located &slot = located[size_t(grid.index(i, j))];
        if (score < -1e-9 || score <= slot.score) continue;
        slot.point = {int(f), weights};
        slot.score = score;
      }
  }
}

// Each branch vertex takes the grid point nearest it; returns the grid points' local degrees.
std::vector<int> branch_vertices_on_grid(const MappedSurface &surface,
                                         const std::vector<Complex> &flat, Complex w1,
                                         const FlatGrid &grid, const std::vector<int> &local_degree,
                                         const std::vector<int> &face_at_vertex,
                                         std::vector<Located> &located) {
  std::vector<int> grid_degree(located.size(), 0);
  for (size_t v = 0; v < local_degree.size(); ++v) {
    if (local_degree[v] < 2 || face_at_vertex[v] < 0) continue;
    const Eigen::Vector2d at = grid.coordinates(shortest(flat[v] / w1, grid.tau));
    const int g = grid.index(std::llround(at.x()), std::llround(at.y()));
    if (grid_degree[size_t(g)] != 0) continue; // two branch points in one grid cell
    const int f = face_at_vertex[v];
    Eigen::Vector3d weights = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
      if (surface.faces[f][k] == int(v)) weights[k] = 1;
    located[size_t(g)].point = {f, weights};
    located[size_t(g)].score = 1;
    grid_degree[size_t(g)] = local_degree[v];
  }
  return grid_degree;
}

// Each grid cell in two triangles across its shorter diagonal.
void grid_faces(const FlatGrid &grid, const std::vector<int> &vertex_of, LiftedSphere &out) {
  const bool diagonal_a_to_c = std::abs(grid.c - grid.a) <= std::abs(grid.c + grid.a);
  for (int j = 0; j < grid.m; ++j)
    for (int i = 0; i < grid.n; ++i) {
      const int p = grid.index(i, j), q = grid.index(i + 1, j), r = grid.index(i, j + 1),
                s = grid.index(i + 1, j + 1);
      std::array<std::array<int, 3>, 2> cell;
      if (diagonal_a_to_c)
        cell = {{{p, q, r}, {q, s, r}}};
      else
        cell = {{{p, q, s}, {p, s, r}}};
      for (const auto &face : cell) {
        if (vertex_of[face[0]] < 0 || vertex_of[face[1]] < 0 || vertex_of[face[2]] < 0) {
          ++out.unlifted_faces;
          continue;
        }
        out.faces.push_back({vertex_of[face[0]], vertex_of[face[1]], vertex_of[face[2]]});
      }
    }
}

} // namespace

LiftedSphere lift_flat_torus(const MappedSurface &surface, const std::vector<Complex> &flat,
                             const std::array<Complex, 2> &periods,
                             const std::vector<int> &face_layer,
                             const std::vector<int> &local_degree, long long samples) {
  const Complex w1 = periods[0];
  const FlatGrid grid(periods[1] / w1, samples);
  std::vector<Located> located(size_t(grid.n) * size_t(grid.m));
  std::vector<int> face_at_vertex;
  locate_grid_points(surface, flat, w1, grid, located, face_at_vertex);
  const std::vector<int> grid_degree =
      branch_vertices_on_grid(surface, flat, w1, grid, local_degree, face_at_vertex, located);
  LiftedSphere out;
  std::vector<int> vertex_of(located.size(), -1);
  for (size_t g = 0; g < located.size(); ++g) {
    const SurfacePoint &point = located[g].point;
    if (point.face < 0) continue;
    vertex_of[g] = int(out.positions.size());
    const auto &corners = surface.faces[point.face];
    Eigen::Vector3d value = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
      value += point.weights[k] * surface.image[corners[k]];
    out.positions.push_back(position_of(surface, point));
    out.sphere.push_back(value.normalized());
    out.layer.push_back(face_layer.empty() ? 0 : face_layer[point.face]);
    out.local_degree.push_back(grid_degree[g]);
    out.on_boundary.push_back(0);
    out.surface_point.push_back(point);
  }
  grid_faces(grid, vertex_of, out);
  out.folded_lifts = count_folded_lifts(surface, out);
  return out;
}

} // namespace meromorph
