#include "maps/genus0_map.h"

#include <algorithm>
#include <cmath>

#include "common/errors.h"
#include "common/parallel_for.h"
#include "forms/region_extension.h"
#include "mesh/cotan_laplacian.h"
#include "mesh/face_vectors.h"
#include "solvers/reweighted_solve.h"
#include "sphere/plane_triangles.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {

namespace {

int best_shaped_face(const Mesh &mesh, const FaceGeometry &geometry) {
  std::vector<double> areas = geometry.areas;
  std::nth_element(areas.begin(), areas.begin() + long(areas.size() / 2), areas.end());
  const double median = areas[areas.size() / 2];
  const int best = best_shaped_face_among(mesh, [&](size_t f) {
    return !(geometry.areas[f] < 0.5 * median || geometry.areas[f] > 2 * median);
  });
  return std::max(best, 0);
}

} // namespace

std::vector<double> positive_weights(const std::vector<double> &weights,
                                     const std::vector<char> &raise, int &raised) {
  std::vector<double> positive = weights;
  std::vector<double> sorted;
  for (double w : weights)
    if (w > 0) sorted.push_back(w);
  std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
  const double floor = 1e-3 * sorted[sorted.size() / 2];
  for (size_t e = 0; e < positive.size(); ++e)
    if (positive[e] < floor && (raise.empty() || raise[e])) {
      positive[e] = floor;
      ++raised;
    }
  return positive;
}

int best_shaped_face_among(const Mesh &mesh, const std::function<bool(size_t)> &eligible) {
  int best = -1;
  double best_angle = -1;
  for (size_t f = 0; f < mesh.face.size(); ++f) {
    if (!eligible(f)) continue;
    const double smallest = smallest_angle(mesh.face[f]);
    if (smallest > best_angle + pole_angle_tie) {
      best_angle = smallest;
      best = int(f);
    }
  }
  return best;
}

int default_pole_face(const PreparedMesh &prepared) {
  return best_shaped_face(prepared.mesh, prepared.geometry);
}

namespace {

// The pole triangle: 1 / (w - c) at the puncture face's corners, in the face's own frame (w
// relative to its centroid, in units of the square root of its area). Fills the two coordinates
// at those corners and returns them.
std::vector<int> pole_triangle(const Mesh &mesh, const FaceGeometry &geometry, int pole_face,
                               Eigen::VectorXcd &fixed) {
  const MeshFace &face = mesh.face[pole_face];
  std::vector<int> corners;
  Eigen::Vector3d p[3];
  for (int k = 0; k < 3; ++k) {
    corners.push_back(index_of(mesh, face.cV(k)));
    p[k] = face.cP(k).ToEigenVector<Eigen::Vector3d>();
  }
  const Eigen::Vector3d centroid = (p[0] + p[1] + p[2]) / 3.0;
  const Eigen::Vector3d e1 = (p[1] - p[0]).normalized();
  const Eigen::Vector3d e2 = geometry.normal(size_t(pole_face)).cross(e1);
  const double size = std::sqrt(geometry.areas[pole_face]);
  fixed = Eigen::VectorXcd::Zero(long(mesh.vert.size()));
  for (int k = 0; k < 3; ++k) {
    const Complex w((p[k] - centroid).dot(e1) / size, (p[k] - centroid).dot(e2) / size);
    fixed[corners[k]] = 1.0 / w;
  }

  return corners;
}

// Orientation in the plane: every face but the pole face must turn counter-clockwise.
std::vector<int> folds_in_the_plane(const FaceIncidence &in, const std::vector<PlaneValue> &values,
                                    int pole_face) {
  return parallel_select(in.corners.size(), [&](size_t f) {
    if (int(f) == pole_face) return false;
    Complex z[3];
    for (int k = 0; k < 3; ++k)
      z[k] = values[size_t(in.corners[f][k])].w;
    // A face smaller than about 1e-12 of its distance from 0 is below what doubles resolve: no
    // weight can unfold it (a better pole can; see parameterization.cpp).
    return folded_in_the_plane(z);
  });
}

// Scaled so that the median |z| is 1 (a Moebius scaling; centring comes later).
std::vector<PlaneValue> scaled_to_median_one(const Eigen::VectorXcd &z) {
  std::vector<double> radii(size_t(z.size()));
  for (size_t i = 0; i < radii.size(); ++i)
    radii[i] = std::abs(z[long(i)]);
  std::nth_element(radii.begin(), radii.begin() + long(radii.size() / 2), radii.end());
  const double scale = radii[radii.size() / 2] > 0 ? 1.0 / radii[radii.size() / 2] : 1.0;
  std::vector<PlaneValue> values;
  values.reserve(size_t(z.size()));
  for (long i = 0; i < z.size(); ++i)
    values.push_back({z[i] * scale, false});
  return values;
}

// Two steps of iterative refinement (see genus0_map).
constexpr int refinement_steps = 2;

} // namespace

void grow_by_rings(const PreparedMesh &prepared, std::vector<char> &marked, int rings) {
  // Breadth first from the marked ones: the work is the grown region's, not the mesh's per ring.
  std::vector<int> frontier;
  for (size_t v = 0; v < marked.size(); ++v)
    if (marked[v]) frontier.push_back(int(v));
  for (int ring = 0; ring < rings && !frontier.empty(); ++ring) {
    std::vector<int> next;
    for (int v : frontier)
      for (int e : prepared.edges_at_vertex[size_t(v)])
        for (int w : prepared.edges.vertices[size_t(e)])
          if (!marked[size_t(w)]) {
            marked[size_t(w)] = 1;
            next.push_back(w);
          }
    frontier = std::move(next);
  }
}

void region_around_folds(const PreparedMesh &prepared, const std::vector<int> &folded_faces,
                         std::vector<char> &raise, std::vector<char> &region) {
  std::vector<char> near(prepared.mesh.vert.size(), 0);
  for (int f : folded_faces)
    for (int v : prepared.incidence.corners[size_t(f)])
      near[size_t(v)] = 1;
  grow_by_rings(prepared, near, 2);
  const MeshEdges &edges = prepared.edges;
  raise.resize(size_t(edges.edge_count()), 0);
  for (int e = 0; e < edges.edge_count(); ++e)
    if (near[size_t(edges.vertices[size_t(e)][0])] && near[size_t(edges.vertices[size_t(e)][1])])
      raise[size_t(e)] = 1;
  region = std::move(near);
  grow_by_rings(prepared, region, local_rings);
}

bool values_crowd(const MeshEdges &edges, const Eigen::VectorXcd &z) {
  const double scale = z.cwiseAbs().maxCoeff();
  // Whether some edge is shorter than the bound (NaN counts as crowded).
  const double bound = crowding_ratio * scale;
  const int short_edges = chunked_sum(edges.vertices.size(), 0, [&](size_t begin, size_t end) {
    int count = 0;
    for (size_t e = begin; e < end; ++e)
      count += shorter_than(z[edges.vertices[e][0]] - z[edges.vertices[e][1]], bound);
    return count;
  });
  return short_edges > 0 || !(bound >= 0);
}

Eigen::VectorXcd harmonic_extension(const Eigen::SparseMatrix<double> &laplacian,
                                    const MeshEdges &edges, const std::vector<double> &weights,
                                    SolverKind solver, const std::vector<int> &pinned,
                                    const Eigen::VectorXcd &fixed, int refinement_steps,
                                    const std::vector<int> &elimination_order) {
  const std::unique_ptr<LaplacianSolver> factored =
      factor_laplacian(laplacian, solver, pinned, elimination_order);
  return harmonic_extension_by([&](const Eigen::MatrixXd &b) { return factored->solve_columns(b); },
                               laplacian, edges, weights, fixed, refinement_steps);
}

Eigen::VectorXcd harmonic_extension_by(const ColumnSolve &solve,
                                       const Eigen::SparseMatrix<double> &laplacian,
                                       const MeshEdges &edges, const std::vector<double> &weights,
                                       const Eigen::VectorXcd &fixed, int refinement_steps) {
  Eigen::MatrixXd given(fixed.size(), 2);
  given.col(0) = fixed.real();
  given.col(1) = fixed.imag();
  Eigen::MatrixXd x = solve(-(laplacian * given)) + given;
  Eigen::VectorXcd out(fixed.size());
  out.real() = x.col(0);
  out.imag() = x.col(1);
  // Where nothing crowds, one solve is accurate to far below the smallest edge's image: the
  // refinement steps would change nothing a written double shows.
  if (refinement_steps == 0 || !values_crowd(edges, out)) return out;
  for (int step = 0; step < refinement_steps; ++step) {
    Eigen::MatrixXd residual(x.rows(), 2);
    for (int k = 0; k < 2; ++k)
      residual.col(k) = laplacian_of_differences(edges, weights, x.col(k));
    x -= solve(residual);
  }
  out.real() = x.col(0);
  out.imag() = x.col(1);
  return out;
}

Genus0Map genus0_map(const PreparedMesh &prepared, SolverKind solver, int pole_face,
                     const std::vector<char> &raise, const std::vector<char> &cap_to_eliminate_last,
                     const std::vector<int> &elimination_order) {
  const Mesh &mesh = prepared.mesh;
  const MeshEdges &edges = prepared.edges;
  const std::vector<double> &weights = prepared.weights;
  Genus0Map out;
  const FaceGeometry &geometry = prepared.geometry;
  if (pole_face < 0) pole_face = best_shaped_face(mesh, geometry);
  if (pole_face >= int(mesh.face.size()))
    throw ArgumentError("puncture face " + std::to_string(pole_face) + " does not exist");
  out.pole_face = pole_face;

  const std::vector<double> positive = positive_weights(weights, raise, out.raised_weights);
  auto laplacian = std::make_shared<const Eigen::SparseMatrix<double>>(
      cotan_laplacian(int(mesh.vert.size()), edges, positive));

  Eigen::VectorXcd fixed;
  const std::vector<int> corners = pole_triangle(mesh, geometry, pole_face, fixed);

  // Dirichlet problem: L_free z_free = -L_free,pinned z_pinned. Long thin parts crowd into spots
  // far smaller than the map's own scale, where one solve's error (relative to the whole map)
  // can exceed the faces: two steps of iterative refinement make each spot accurate relative to
  // its own size, down to the spacing of doubles.
  const bool cap_last = solver == SolverKind::cholmod && !cap_to_eliminate_last.empty();
  std::shared_ptr<const LaplacianSolver> factored = factor_laplacian(
      *laplacian, solver, corners,
      !cap_last || !elimination_order.empty()
          ? elimination_order
          : elimination_order_with_last(*laplacian, corners, cap_to_eliminate_last));
  out.elimination_order = corners;
  const std::vector<int> order = factored->elimination_order();
  out.elimination_order.insert(out.elimination_order.end(), order.begin(), order.end());
  const Eigen::VectorXcd z =
      harmonic_extension_by([&](const Eigen::MatrixXd &b) { return factored->solve_columns(b); },
                            *laplacian, edges, positive, fixed, refinement_steps);
  if (cap_last) {
    out.cap_last.corners = corners;
    for (size_t k = order.size(); k-- > 0 && cap_to_eliminate_last[size_t(order[k])];)
      out.cap_last.cap.push_back(order[k]);
    out.cap_last.solver = std::move(factored);
    out.cap_last.laplacian = std::move(laplacian);
    out.cap_last.weights = positive;
  }
  out.values = scaled_to_median_one(z);
  out.folded_faces = folds_in_the_plane(prepared.incidence, out.values, pole_face);
  out.weights = positive;
  return out;
}

std::optional<Genus0Map> genus0_map_reweighted(const PreparedMesh &prepared, const Genus0Map &first,
                                               const std::vector<char> &raise) {
  const CapLastFactor &factor = first.cap_last;
  if (!factor.solver) return std::nullopt;
  const Mesh &mesh = prepared.mesh;
  const int n = int(mesh.vert.size());
  Genus0Map out;
  out.pole_face = first.pole_face;
  out.elimination_order = first.elimination_order;
  const std::vector<double> positive =
      positive_weights(prepared.weights, raise, out.raised_weights);
  const ReweightedSolve solve(*factor.solver, n, factor.corners, prepared.edges, factor.weights,
                              positive);
  if (!solve.usable()) return std::nullopt;
  Eigen::VectorXcd fixed;
  pole_triangle(mesh, prepared.geometry, out.pole_face, fixed);
  const Eigen::VectorXcd z =
      harmonic_extension_by([&](const Eigen::MatrixXd &b) { return solve.solve_columns(b); },
                            cotan_laplacian(n, prepared.edges, positive), prepared.edges, positive,
                            fixed, refinement_steps);
  out.values = scaled_to_median_one(z);
  out.folded_faces = folds_in_the_plane(prepared.incidence, out.values, out.pole_face);
  out.weights = positive;
  return out;
}

Genus0Map genus0_map_again_in(const PreparedMesh &prepared, const Genus0Map &first,
                              const std::vector<char> &raise, const std::vector<char> &region) {
  const int n = int(prepared.mesh.vert.size());
  Genus0Map out;
  out.pole_face = first.pole_face;
  out.elimination_order = first.elimination_order;
  const std::vector<double> positive =
      positive_weights(prepared.weights, raise, out.raised_weights);
  std::vector<char> free = region;
  for (int v : prepared.incidence.corners[size_t(first.pole_face)])
    free[size_t(v)] = 0;
  Eigen::VectorXcd given(n);
  for (int v = 0; v < n; ++v)
    given[v] = first.values[size_t(v)].w;
  const Eigen::VectorXcd z = harmonic_extension_in_region(prepared, positive, free, given);
  out.values.reserve(size_t(n));
  for (int i = 0; i < n; ++i)
    out.values.push_back({z[i], false});
  out.folded_faces = folds_in_the_plane(prepared.incidence, out.values, out.pole_face);
  out.weights = positive;
  return out;
}

} // namespace meromorph
