#include "maps/form_ratio_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>

#include "common/parallel_for.h"
#include "mesh/face_vectors.h"
#include "mesh/mesh_edges.h"
#include "solvers/cluster_jacobi.h"
#include "solvers/factorization_threads.h"
#include "solvers/hermitian_cg.h"
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
// triangles another 0.2 GB); empty (0 x 0) when an entry is not finite. Returned as itself (Eigen
// 3.4's SparseMatrix has no move constructor: an std::optional of it, or a move into an
// argument taken by value, copied its arrays).
Eigen::SparseMatrix<Complex> hermitian_matrix(const MeshEdges &edges, const ChartSystem &system) {
  auto finite = [](Complex z) { return std::isfinite(z.real()) && std::isfinite(z.imag()); };
  Eigen::SparseMatrix<Complex> lower;
  Eigen::VectorXi per_column = Eigen::VectorXi::Ones(system.unknowns);
  for (size_t e = 0; e < system.along_edge.size(); ++e) {
    if (!system.edge_in_system[e]) continue;
    if (!finite(system.along_edge[e])) return lower;
    ++per_column[std::min(system.id[size_t(edges.vertices[e][0])],
                          system.id[size_t(edges.vertices[e][1])])];
  }
  for (const Complex &entry : system.diagonal)
    if (!finite(entry)) return lower;
  lower.resize(system.unknowns, system.unknowns);
  lower.reserve(per_column);
  for (size_t i = 0; i < system.diagonal.size(); ++i)
    lower.insert(int(i), int(i)) = system.diagonal[i];
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

// One chart's system as it is solved: conjugate gradients, paused between calls (a screening
// solve goes on to the full one from where it stopped), and CHOLMOD where they do not converge.
// Its matrix H is Hermitian positive definite: its data term makes it a screened problem whose
// condition does not grow with the mesh, so conjugate gradients converge in a number of steps
// independent of its size, each a product with H. Needles and the close vertices of raw
// marching cubes couple pairs of unknowns stiffly: then the steps are preconditioned over
// clusters of them (solvers/cluster_jacobi.h), else by the diagonal.
struct ChartSolve {
  std::vector<int> vertex; // per unknown its mesh vertex
  std::optional<HermitianConjugateGradients> iterated;
  std::optional<Eigen::VectorXcd> exact; // where conjugate gradients did not converge
  int steps = 0;

  // `start` per mesh vertex. Nothing to solve where the system is empty or not finite (the
  // forms are not resolved there).
  ChartSolve(const MeshEdges &edges, ChartSystem system, const std::vector<Complex> &start) {
    // (CHOLMOD cannot analyse an empty matrix, and Eigen does not check that it could.)
    if (system.unknowns == 0 || !system.right.allFinite()) return;
    Eigen::SparseMatrix<Complex> matrix = hermitian_matrix(edges, system);
    if (matrix.rows() == 0) return;
    system.diagonal = {};
    system.along_edge = {};
    system.edge_in_system = {};
    vertex.resize(size_t(system.unknowns));
    Eigen::VectorXcd first(system.unknowns);
    for (size_t v = 0; v < system.id.size(); ++v)
      if (system.id[v] >= 0) {
        vertex[size_t(system.id[v])] = int(v);
        first[system.id[v]] = start[v];
      }
    system.id = {};
    if (!first.allFinite()) first.setZero();
    const bool stiff = stiffly_coupled(
        {int(matrix.rows()), matrix.outerIndexPtr(), matrix.innerIndexPtr(), matrix.valuePtr()});
    iterated.emplace(std::move(matrix), std::move(system.right), std::move(first),
                     stiff ? HermitianConjugateGradients::Preconditioner::clusters
                           : HermitianConjugateGradients::Preconditioner::diagonal);
  }

  // On to the relative residual `tolerance`; CHOLMOD (supernodal, complex) where conjugate
  // gradients do not converge within iterative_steps.
  void advance(double tolerance) {
    if (!iterated) return;
    const bool converged = iterated->advance(tolerance, iterative_steps);
    steps = iterated->steps();
    if (converged && iterated->solution().allFinite()) return;
    {
      const FactorizationThreads threads; // solvers/factorization_threads.h
      Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<Complex>, Eigen::Lower> factored(
          iterated->lower());
      if (factored.info() == Eigen::Success) {
        Eigen::VectorXcd solution = factored.solve(iterated->right());
        if (factored.info() == Eigen::Success) exact = std::move(solution);
      }
    }
    iterated.reset(); // (not solved: the guess stays)
  }

  // The values per mesh vertex: the solution where it is finite, else `guess`.
  std::vector<Complex> values(const std::vector<Complex> &guess) const {
    std::vector<Complex> out(guess);
    const Eigen::VectorXcd *solution = exact ? &*exact : iterated ? &iterated->solution() : nullptr;
    if (!solution) return out;
    for (size_t i = 0; i < vertex.size(); ++i) {
      const Complex value = (*solution)[long(i)];
      if (std::isfinite(value.real()) && std::isfinite(value.imag()))
        out[size_t(vertex[i])] = value;
    }
    return out;
  }
};

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

struct RatioMap::Charts {
  ChartGuess guess;
  std::optional<ChartSolve> zero, pole; // F / scale, and G = scale / F
};

RatioMap::RatioMap(const PreparedMesh &prepared, RatioDz dz, const std::vector<PlaneValue> *start)
    : charts_(std::make_unique<Charts>()) {
  const Mesh &mesh = prepared.mesh;
  const MeshEdges &edges = prepared.edges;
  const size_t face_count = mesh.face.size();
  const FaceGeometry &geometry = prepared.geometry;
  const FaceIncidence &in = prepared.incidence;
  // The forms' dz coefficients per face: their ratio is the function's sample there.
  // (Named references, not a structured binding: C++17 lambdas cannot capture one.)
  std::vector<Complex> &top = dz[0], &bottom = dz[1];
  charts_->guess = chart_guess(prepared, top, bottom);
  const ChartGuess &guess = charts_->guess;
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
  // Where `start` gives values, each chart starts from them where they are finite.
  std::vector<Complex> start_f, start_g;
  if (start) {
    start_f = guess.f;
    start_g = guess.g;
    parallel_for(start_f.size(), [&](size_t v) {
      const PlaneValue &value = (*start)[v];
      const Complex w = value.w / guess.scale;
      if (value.infinite || !std::isfinite(w.real()) || !std::isfinite(w.imag())) return;
      if (near_zero[v]) start_f[v] = w;
      if (near_pole[v] && std::abs(w) > 0) start_g[v] = 1.0 / w;
    });
  }
  // F / scale where |F / scale| < chart_bound, G = scale / F where |F / scale| > 1 / chart_bound,
  // the two charts' systems made at once, one per core, and then their solves (the samples let
  // go first: they were 12 MB of the peak at 178k vertices).
  std::optional<ChartSystem> zero_system, pole_system;
  parallel_pair(
      [&] {
        zero_system.emplace(
            chart_system(mesh, edges, in, geometry, near_zero, ratio_f, known_f, guess.f));
      },
      [&] {
        pole_system.emplace(
            chart_system(mesh, edges, in, geometry, near_pole, ratio_g, known_g, guess.g));
      });
  std::vector<Complex>().swap(ratio_f);
  std::vector<Complex>().swap(ratio_g);
  std::vector<char>().swap(known_f);
  std::vector<char>().swap(known_g);
  parallel_pair(
      [&] { charts_->zero.emplace(edges, std::move(*zero_system), start ? start_f : guess.f); },
      [&] { charts_->pole.emplace(edges, std::move(*pole_system), start ? start_g : guess.g); });
}

RatioMap::RatioMap(RatioMap &&) noexcept = default;
RatioMap &RatioMap::operator=(RatioMap &&) noexcept = default;
RatioMap::~RatioMap() = default;

void RatioMap::advance(double tolerance) {
  Charts &charts = *charts_;
  parallel_pair([&] { charts.zero->advance(tolerance); }, [&] { charts.pole->advance(tolerance); });
}

std::vector<PlaneValue> RatioMap::values(double tolerance) {
  advance(tolerance);
  const Charts &charts = *charts_;
  const ChartGuess &guess = charts.guess;
  std::vector<PlaneValue> values =
      blended_values(guess, charts.zero->values(guess.f), charts.pole->values(guess.g));
  parallel_for(values.size(), [&](size_t v) { values[v].w *= guess.scale; });
  return values;
}

int RatioMap::steps() const {
  return std::max(charts_->zero->steps, charts_->pole->steps);
}

std::vector<PlaneValue> form_ratio_map(const PreparedMesh &prepared, RatioDz dz,
                                       const RatioSolve &how) {
  return RatioMap(prepared, std::move(dz), how.start).values(how.tolerance);
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
