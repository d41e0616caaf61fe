#include "maps/form_ratio_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <optional>

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include "common/factorization_threads.h"
#include "common/parallel_for.h"
#include "forms/cluster_jacobi.h"
#include "mesh/face_vectors.h"
#include "mesh/mesh_edges.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {
namespace {

// |F| is measured against its median over the vertices (F / scale: ChartGuess), so the two
// charts split the mesh evenly and run as long as each other, one per core. Each chart holds
// |F / scale| < chart_bound (or > 1 / chart_bound): where the map covers the sphere evenly, 72%
// of the mesh each (at 2.5: 86%, and up to all of it without the scale). The two solutions are
// blended on the sphere where 1 / blend_bound < |F / scale| < blend_bound, inside both with a
// margin of 9 degrees of the sphere on either side. (Measured on 20 generated and shared
// genus-2 to -10 meshes, needles and raw marching cubes included, against charts to 2.5
// blended from 1/1.6 to 1.6 without the scale: the mean angle error 1.4% lower to 0.3% higher
// where the same pair is kept; the raw marching-cubes genus-10 surface keeps another pair of
// almost the same crowding, 3.9% higher; at 178k vertices of raw marching cubes with needles
// the largest chart 112k unknowns instead of 177k.)
constexpr double chart_bound = 1.6, blend_bound = 1.25;

// Conjugate gradients on a chart's system: the steps allowed before CHOLMOD takes over (the
// relative residual asked: RatioSolve in the header).
constexpr int iterative_steps = 1000;

// A Hermitian system over the vertices of one region, numbered densely, assembled in place: its
// diagonal per unknown and, per mesh edge with both ends in the region, the entry in the edge's
// direction (the opposite entry is its conjugate). No per-face entry lists: at a million vertices
// those took more memory than everything else.
struct ChartSystem {
  std::vector<int> id; // per mesh vertex: its unknown, -1 outside the region
  int unknowns = 0;
  std::vector<Complex> diagonal;    // per unknown
  std::vector<Complex> along_edge;  // per mesh edge: H(id[from], id[to])
  std::vector<char> edge_in_system; // per mesh edge: a face of the region has it
  Eigen::VectorXcd right;
  double largest_data_weight = 0;
};

// Face f's share: the data term (F at the centroid = mean of the corners, weighted by the face's
// share of the area and the sphere's metric 1 / (1 + |ratio|^2)^2) when its sample is known, and
// `stiffness` times the conformal energy (Dirichlet energy minus signed image area, zero for a
// similarity on the face). `c`: the corners' unknowns.
void add_face(const MeshFace &face, const MeshEdges &edges, size_t f, const std::array<int, 3> &c,
              double area_share, bool ratio_known, Complex ratio, ChartSystem &system) {
  const double stiffness = 1.0; // conformal energy against the data's area-weighted misfit
  // The sphere's metric over the face (1 at F = 0): both terms measure the map on the sphere.
  const double metric = ratio_known ? 1.0 / std::pow(1.0 + std::norm(ratio), 2) : 0.0;
  double data = 0; // the data term's weight on every pair of corners
  if (ratio_known) {
    data = area_share * metric / 9.0;
    system.largest_data_weight = std::max(system.largest_data_weight, data);
    for (int a : c) {
      system.diagonal[size_t(a)] += data;
      system.right[a] += 3.0 * data * ratio;
    }
  }
  // The cotangent weight of each corner, on the side opposite it; a corner without area adds
  // neither it nor the image area along the side leaving it.
  double opposite[3] = {0, 0, 0};
  bool flat[3] = {true, true, true};
  for (int k = 0; k < 3; ++k) {
    const Point3 u = face.cP((k + 1) % 3) - face.cP(k), v = face.cP((k + 2) % 3) - face.cP(k);
    const double cross = (u ^ v).Norm();
    if (!(cross > 0)) continue;
    flat[k] = false;
    opposite[k] = stiffness * metric * 0.25 * (u * v) / cross;
    system.diagonal[size_t(c[(k + 1) % 3])] += opposite[k];
    system.diagonal[size_t(c[(k + 2) % 3])] += opposite[k];
  }
  // Minus the signed image area, 1/2 Im(conj(F_a) F_b) along the side a -> b.
  const Complex area = stiffness * metric * Complex(0, -0.25);
  for (int k = 0; k < 3; ++k) { // side k: corner k -> corner k + 1
    const Complex entry = data - opposite[(k + 2) % 3] - (flat[k] ? Complex(0, 0) : area);
    const size_t e = size_t(edges.face_edges[f][k]);
    system.along_edge[e] += edges.face_signs[f][k] > 0 ? entry : std::conj(entry);
    system.edge_in_system[e] = 1;
  }
}

ChartSystem chart_system(const Mesh &mesh, const MeshEdges &edges, const FaceIncidence &in,
                         const FaceGeometry &geometry, const std::vector<char> &region,
                         const std::vector<Complex> &ratio, const std::vector<char> &ratio_known,
                         const std::vector<Complex> &guess) {
  ChartSystem system;
  system.id.assign(region.size(), -1);
  for (size_t v = 0; v < region.size(); ++v)
    if (region[v]) system.id[v] = system.unknowns++;
  double mean_area = 0;
  for (double a : geometry.areas)
    mean_area += a;
  mean_area /= double(std::max<size_t>(1, geometry.areas.size()));
  system.diagonal.assign(size_t(system.unknowns), Complex(0, 0));
  system.along_edge.assign(size_t(edges.edge_count()), Complex(0, 0));
  system.edge_in_system.assign(size_t(edges.edge_count()), 0);
  system.right = Eigen::VectorXcd::Zero(system.unknowns);
  for (size_t f = 0; f < in.corners.size(); ++f) {
    const auto &corners = in.corners[f];
    if (!region[corners[0]] || !region[corners[1]] || !region[corners[2]]) continue;
    add_face(mesh.face[f], edges, f,
             {system.id[corners[0]], system.id[corners[1]], system.id[corners[2]]},
             geometry.areas[f] / mean_area, ratio_known[f], ratio[f], system);
  }
  // A faint pull towards `guess` keeps every vertex determined.
  const double pull = 1e-9 * (system.largest_data_weight > 0 ? system.largest_data_weight : 1.0);
  for (size_t v = 0; v < region.size(); ++v)
    if (system.id[v] >= 0) {
      system.diagonal[size_t(system.id[v])] += pull;
      system.right[system.id[v]] += pull * guess[v];
    }
  return system;
}

// The lower triangle of `system`'s matrix (all that conjugate gradients and CHOLMOD read of a
// Hermitian matrix), written in place: each column's room counted first (its diagonal and one
// entry per edge of the system whose other end has a larger unknown), no list of entries and no
// transposed copy (at 2.7M vertices those were 0.4 GB of the peak, both charts together; both
// triangles another 0.2 GB); empty when an entry is not finite.
std::optional<Eigen::SparseMatrix<Complex>> hermitian_matrix(const MeshEdges &edges,
                                                             const ChartSystem &system) {
  auto finite = [](Complex z) { return std::isfinite(z.real()) && std::isfinite(z.imag()); };
  Eigen::VectorXi per_column = Eigen::VectorXi::Ones(system.unknowns);
  for (size_t e = 0; e < system.along_edge.size(); ++e) {
    if (!system.edge_in_system[e]) continue;
    if (!finite(system.along_edge[e])) return std::nullopt;
    ++per_column[std::min(system.id[size_t(edges.vertices[e][0])],
                          system.id[size_t(edges.vertices[e][1])])];
  }
  Eigen::SparseMatrix<Complex> lower(system.unknowns, system.unknowns);
  lower.reserve(per_column);
  for (size_t i = 0; i < system.diagonal.size(); ++i) {
    if (!finite(system.diagonal[i])) return std::nullopt;
    lower.insert(int(i), int(i)) = system.diagonal[i];
  }
  for (size_t e = 0; e < system.along_edge.size(); ++e) {
    if (!system.edge_in_system[e]) continue;
    const int from = system.id[size_t(edges.vertices[e][0])];
    const int to = system.id[size_t(edges.vertices[e][1])];
    // H(from, to) is the edge's entry, H(to, from) its conjugate.
    if (from > to)
      lower.insert(from, to) = system.along_edge[e];
    else
      lower.insert(to, from) = std::conj(system.along_edge[e]);
  }
  lower.makeCompressed();
  return lower;
}

// Conjugate gradients on H x = r (`hermitian`: H's lower triangle) from `start` to the relative
// residual `tolerance`, preconditioned by `Preconditioner`; empty where they do not converge
// within iterative_steps. `steps`: the steps taken.
template <class Preconditioner>
std::optional<Eigen::VectorXcd>
conjugate_gradients(const Eigen::SparseMatrix<Complex> &hermitian, const Eigen::VectorXcd &right,
                    const Eigen::VectorXcd &start, double tolerance, int &steps) {
  Eigen::ConjugateGradient<Eigen::SparseMatrix<Complex>, Eigen::Lower, Preconditioner> iterated;
  iterated.setTolerance(tolerance);
  iterated.setMaxIterations(iterative_steps);
  iterated.compute(hermitian);
  Eigen::VectorXcd solution = iterated.solveWithGuess(right, start);
  steps = int(iterated.iterations());
  if (iterated.info() == Eigen::Success && solution.allFinite()) return solution;
  return std::nullopt;
}

// The Hermitian positive definite system H x = r. Its data term makes it a screened problem
// whose condition does not grow with the mesh: conjugate gradients from `start` (the chart's
// first guess, or an earlier solve's values) to the relative residual `tolerance` converge in a
// number of steps independent of its size, each a product with H. Needles and the close vertices of
// raw marching cubes couple pairs of unknowns stiffly: then the steps are preconditioned over
// clusters of them (forms/cluster_jacobi.h), else by the diagonal. Where they do not converge,
// CHOLMOD factors it (supernodal, complex). H is held as its lower triangle. Empty when it cannot
// be solved. `steps`: the conjugate gradients' steps.
std::optional<Eigen::VectorXcd> solve_hermitian(const MeshEdges &edges, ChartSystem &system,
                                                Eigen::VectorXcd start, double tolerance,
                                                int &steps) {
  const int n = system.unknowns;
  // (CHOLMOD cannot analyse an empty matrix, and Eigen does not check that it could.)
  if (n == 0) return std::nullopt;
  if (!system.right.allFinite()) return std::nullopt;
  std::optional<Eigen::SparseMatrix<Complex>> matrix = hermitian_matrix(edges, system);
  if (!matrix) return std::nullopt; // the forms are not resolved here
  system.diagonal = {};
  system.along_edge = {};
  const Eigen::SparseMatrix<Complex> &hermitian = *matrix;
  if (!start.allFinite()) start.setZero();
  std::optional<Eigen::VectorXcd> iterated =
      stiffly_coupled(
          {n, hermitian.outerIndexPtr(), hermitian.innerIndexPtr(), hermitian.valuePtr()})
          ? conjugate_gradients<ClusterJacobi>(hermitian, system.right, start, tolerance, steps)
          : conjugate_gradients<Eigen::DiagonalPreconditioner<Complex>>(hermitian, system.right,
                                                                        start, tolerance, steps);
  if (iterated) return iterated;
  const FactorizationThreads threads(hermitian.rows()); // common/factorization_threads.h
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<Complex>, Eigen::Lower> factored(hermitian);
  if (factored.info() != Eigen::Success) return std::nullopt;
  Eigen::VectorXcd solution = factored.solve(system.right);
  if (factored.info() != Eigen::Success) return std::nullopt;
  return solution;
}

// In one chart of the sphere: values F at the vertices of `region` that fit the face samples
// `ratio` while keeping the piecewise-linear map conformal (see add_face), solved from `start`
// (per mesh vertex) to the relative residual `tolerance`; `guess` where the system cannot be
// solved or a value comes out not finite. `steps`: the conjugate gradients' steps (0: none).
std::vector<Complex> solve_chart(const Mesh &mesh, const MeshEdges &edges, const FaceIncidence &in,
                                 const FaceGeometry &geometry, const std::vector<char> &region,
                                 const std::vector<Complex> &ratio,
                                 const std::vector<char> &ratio_known,
                                 const std::vector<Complex> &guess,
                                 const std::vector<Complex> &start, double tolerance, int &steps) {
  ChartSystem system = chart_system(mesh, edges, in, geometry, region, ratio, ratio_known, guess);
  Eigen::VectorXcd first(system.unknowns);
  for (size_t v = 0; v < region.size(); ++v)
    if (system.id[v] >= 0) first[system.id[v]] = start[v];
  // (The values per mesh vertex are made after the solve, not held beside its vectors.)
  const std::optional<Eigen::VectorXcd> solution =
      solve_hermitian(edges, system, std::move(first), tolerance, steps);
  std::vector<Complex> values(guess);
  if (!solution) return values;
  for (size_t v = 0; v < region.size(); ++v) {
    const int i = system.id[v];
    if (i >= 0 && std::isfinite((*solution)[i].real()) && std::isfinite((*solution)[i].imag()))
      values[v] = (*solution)[i];
  }
  return values;
}

// The two charts' first guesses: per vertex the area-weighted mean on the sphere of its faces'
// samples F = top / bottom, measured against the median of |F|: F / scale in the chart of 0 where
// |F / scale| < chart_bound, G = scale / F in the chart of infinity where |F / scale| >
// 1 / chart_bound.
struct ChartGuess {
  std::vector<char> near_zero, near_pole;
  std::vector<double> size;  // |F| / scale
  std::vector<Complex> f, g; // F / scale, scale / F
  double scale = 1;          // the median of |F| over the vertices
};

// Per vertex the area-weighted mean on the sphere of its faces' samples F = top / bottom (unit
// vectors): each face's sample first, then each vertex's sum over its faces in face order.
std::vector<Eigen::Vector3d> mean_samples(const PreparedMesh &prepared,
                                          const std::vector<Complex> &top,
                                          const std::vector<Complex> &bottom) {
  const size_t face_count = prepared.mesh.face.size();
  const FaceGeometry &geometry = prepared.geometry;
  const FaceIncidence &in = prepared.incidence;
  std::vector<Eigen::Vector3d> sample(face_count); // area-weighted, on the sphere
  parallel_for(face_count, [&](size_t f) {
    const bool pole = std::abs(bottom[f]) == 0.0;
    sample[f] =
        geometry.areas[f] * to_sphere(PlaneValue{pole ? Complex() : top[f] / bottom[f], pole});
  });
  std::vector<Eigen::Vector3d> mean(prepared.mesh.vert.size());
  parallel_for(mean.size(), [&](size_t v) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int f : in.faces_of_vertex[v])
      sum += sample[size_t(f)];
    mean[v] = sum.normalized();
  });
  return mean;
}

ChartGuess chart_guess(const PreparedMesh &prepared, const std::vector<Complex> &top,
                       const std::vector<Complex> &bottom) {
  const int n = int(prepared.mesh.vert.size());
  const std::vector<Eigen::Vector3d> mean = mean_samples(prepared, top, bottom);
  ChartGuess out{std::vector<char>(size_t(n)), std::vector<char>(size_t(n)),
                 std::vector<double>(size_t(n)), std::vector<Complex>(size_t(n)),
                 std::vector<Complex>(size_t(n))};
  std::vector<char> &near_zero = out.near_zero, &near_pole = out.near_pole;
  std::vector<double> &size = out.size;
  std::vector<Complex> &guess_f = out.f, &guess_g = out.g;
  parallel_for(size_t(n), [&](size_t v) {
    const PlaneValue guess = to_plane_value(mean[v]);
    size[v] = guess.infinite ? HUGE_VAL : std::abs(guess.w);
  });
  // The charts split where |F| is its median over the vertices: half the mesh each.
  if (n > 0) {
    std::vector<double> sizes(size);
    std::nth_element(sizes.begin(), sizes.begin() + n / 2, sizes.end());
    const double median = sizes[size_t(n / 2)];
    if (median > 0 && std::isfinite(median)) out.scale = median;
  }
  parallel_for(size_t(n), [&](size_t v) {
    const PlaneValue guess = to_plane_value(mean[v]);
    const Complex w = guess.w / out.scale;
    size[v] /= out.scale;
    near_zero[v] = size[v] < chart_bound;
    near_pole[v] = size[v] > 1.0 / chart_bound;
    if (near_zero[v]) guess_f[v] = w;
    if (near_pole[v] && size[v] > 0 && !guess.infinite) guess_g[v] = 1.0 / w;
  });
  return out;
}

// F where |F| < 1 / blend_bound, 1 / G where |F| > blend_bound, blended on the sphere between.
std::vector<PlaneValue> blended_values(const ChartGuess &guess, const std::vector<Complex> &f,
                                       const std::vector<Complex> &g) {
  const int n = int(f.size());
  const std::vector<char> &near_zero = guess.near_zero, &near_pole = guess.near_pole;
  const std::vector<double> &size = guess.size;
  std::vector<PlaneValue> values(static_cast<size_t>(n));
  for (int v = 0; v < n; ++v) {
    if (!near_pole[v]) {
      values[v] = PlaneValue{f[v], false};
      continue;
    }
    const Eigen::Vector3d pole_side =
        std::abs(g[v]) == 0.0 ? Eigen::Vector3d(0, 0, 1) : to_sphere(1.0 / g[v]);
    if (!near_zero[v]) {
      values[v] = to_plane_value(pole_side);
      continue;
    }
    const double s = std::clamp(0.5 + std::log(size[v]) / (2.0 * std::log(blend_bound)), 0.0, 1.0);
    const double t = s * s * (3 - 2 * s);
    values[v] = to_plane_value(((1 - t) * to_sphere(f[v]) + t * pole_side).normalized());
  }
  return values;
}

} // namespace

std::vector<PlaneValue> form_ratio_map(const PreparedMesh &prepared, RatioDz dz,
                                       const RatioSolve &how) {
  const Mesh &mesh = prepared.mesh;
  const MeshEdges &edges = prepared.edges;
  const size_t face_count = mesh.face.size();
  const FaceGeometry &geometry = prepared.geometry;
  const FaceIncidence &in = prepared.incidence;
  // The forms' dz coefficients per face: their ratio is the function's sample there.
  // (Named references, not a structured binding: C++17 lambdas cannot capture one.)
  std::vector<Complex> &top = dz[0], &bottom = dz[1];
  const ChartGuess guess = chart_guess(prepared, top, bottom);
  const std::vector<char> &near_zero = guess.near_zero, &near_pole = guess.near_pole;
  std::vector<Complex> ratio_f(face_count), ratio_g(face_count);
  std::vector<char> known_f(face_count), known_g(face_count);
  parallel_for(face_count, [&](size_t f) {
    ratio_f[f] = top[f] / (guess.scale * bottom[f]);
    ratio_g[f] = guess.scale * bottom[f] / top[f];
    known_f[f] = std::isfinite(ratio_f[f].real()) && std::isfinite(ratio_f[f].imag());
    known_g[f] = std::isfinite(ratio_g[f].real()) && std::isfinite(ratio_g[f].imag());
  });
  std::vector<Complex>().swap(top); // not held beside the charts' systems
  std::vector<Complex>().swap(bottom);
  // Where `how` gives values to start from, each chart starts from them where they are finite.
  std::vector<Complex> start_f, start_g;
  if (how.start) {
    start_f = guess.f;
    start_g = guess.g;
    parallel_for(start_f.size(), [&](size_t v) {
      const PlaneValue &value = (*how.start)[v];
      const Complex w = value.w / guess.scale;
      if (value.infinite || !std::isfinite(w.real()) || !std::isfinite(w.imag())) return;
      if (near_zero[v]) start_f[v] = w;
      if (near_pole[v] && std::abs(w) > 0) start_g[v] = 1.0 / w;
    });
  }
  // F / scale where |F / scale| < chart_bound, G = scale / F where |F / scale| > 1 / chart_bound,
  // the two charts at once (each solve runs on one core); blended between.
  int steps_f = 0, steps_g = 0;
  std::future<std::vector<Complex>> pole_chart = std::async(std::launch::async, [&] {
    return solve_chart(mesh, edges, in, geometry, near_pole, ratio_g, known_g, guess.g,
                       how.start ? start_g : guess.g, how.tolerance, steps_g);
  });
  const std::vector<Complex> f =
      solve_chart(mesh, edges, in, geometry, near_zero, ratio_f, known_f, guess.f,
                  how.start ? start_f : guess.f, how.tolerance, steps_f);
  const std::vector<Complex> g = pole_chart.get();
  if (how.steps) *how.steps = std::max(steps_f, steps_g);
  std::vector<PlaneValue> values = blended_values(guess, f, g);
  parallel_for(values.size(), [&](size_t v) { values[v].w *= guess.scale; });
  return values;
}

int guessed_crowding(const PreparedMesh &prepared, const RatioDz &dz) {
  return crowded_faces(prepared.incidence, mean_samples(prepared, dz[0], dz[1]));
}

int crowded_faces(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere) {
  return int(parallel_select(in.corners.size(), [&](size_t f) {
               const Eigen::Vector3d &a = sphere[size_t(in.corners[f][0])],
                                     &b = sphere[size_t(in.corners[f][1])],
                                     &c = sphere[size_t(in.corners[f][2])];
               return std::max({(a - b).squaredNorm(), (b - c).squaredNorm(),
                                (c - a).squaredNorm()}) > 1.0;
             }).size());
}

} // namespace meromorph
