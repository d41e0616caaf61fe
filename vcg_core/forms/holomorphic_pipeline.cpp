#include "forms/holomorphic_pipeline.h"

#include <chrono>

#include <Eigen/Dense>

#include "common/errors.h"
#include "common/job_threads.h"
#include "common/parallel_for.h"
#include "common/stage_clock.h"
#include "forms/harmonic_forms.h"
#include "forms/holomorphic_forms.h"
#include "forms/intrinsic_delaunay.h"
#include "forms/periods.h"
#include "mesh/cotan_laplacian.h"
#include "mesh/face_vectors.h"
#include "mesh/prepared_mesh.h"
#include "mesh/unit_scale.h"
#include "mesh/validation.h"

namespace meromorph {
namespace {

double closedness(const MeshEdges &edges, const Eigen::VectorXd &form) {
  double worst = 0;
  for (size_t f = 0; f < edges.face_edges.size(); ++f) {
    double sum = 0;
    for (int k = 0; k < 3; ++k)
      sum += edges.face_signs[f][k] * form[edges.face_edges[f][k]];
    worst = std::max(worst, std::abs(sum));
  }
  return worst;
}

// How closed and co-closed the harmonic forms came out.
void measure_residuals(int vertex_count, const MeshEdges &edges, const std::vector<double> &weights,
                       HolomorphicForms &out) {
  const size_t n = out.harmonic.size();
  std::vector<double> closed(n), coclosed(n);
  parallel_for( // the forms over the cores
      n,
      [&](size_t j) {
        const Eigen::VectorXd &h = out.harmonic[j];
        closed[j] = closedness(edges, h);
        const Eigen::VectorXd divergence = weighted_divergence(vertex_count, edges, weights, h);
        double scale = 0;
        for (int e = 0; e < edges.edge_count(); ++e)
          scale = std::max(scale, std::abs(weights[e] * h[e]));
        coclosed[j] = divergence.tail(vertex_count - 1).cwiseAbs().maxCoeff() / scale;
      },
      2);
  for (size_t j = 0; j < n; ++j) {
    out.closedness_residual = std::max(out.closedness_residual, closed[j]);
    out.coclosedness_residual = std::max(out.coclosedness_residual, coclosed[j]);
  }
}

// The periods of tau_j = h_j + i *h_j along the primal loops, the canonical basis from the
// intersection numbers, the A- and B-periods of phi_k = sum_j P_jk tau_j, the Riemann matrix
// (and genus 1's reduced modulus), with the intersection numbers from `intersections` (the
// integrals of h_j ^ h_k, summed in the conjugate fit's pass). Returns the basis P.
Eigen::MatrixXd canonical_periods(const Eigen::MatrixXd &intersections, HolomorphicForms &out) {
  const int n = 2 * out.genus;
  // Periods of tau_j = h_j + i *h_j along the primal loops.
  Eigen::MatrixXd real_periods(n, n);
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k)
      real_periods(j, k) = integrate(out.harmonic[j], out.homology.primal_loops[k]);
  out.loop_periods =
      real_periods.cast<std::complex<double>>() +
      std::complex<double>(0, 1) * (out.conjugate * real_periods).cast<std::complex<double>>();

  // Coordinates in the omega basis: the loop integrals of omega are +-delta.
  Eigen::VectorXd loop_sign(n);
  for (int k = 0; k < n; ++k)
    loop_sign[k] = integrate(out.homology.dual_forms[k], out.homology.primal_loops[k]);

  out.wedge = rounded_intersections(intersections, &out.wedge_rounding);
  out.symplectic = symplectic_basis(out.wedge);
  const Eigen::MatrixXd basis = out.symplectic.cast<double>();
  const Eigen::MatrixXd basis_inverse = basis.inverse();

  // phi_k = holomorphic form of alpha_k = sum_j P_jk tau_j; its periods along the canonical cycles.
  const int g = out.genus;
  out.a_periods.resize(g, g);
  out.b_periods.resize(g, g);
  for (int k = 0; k < g; ++k) {
    Eigen::VectorXcd coordinates = Eigen::VectorXcd::Zero(n);
    for (int j = 0; j < n; ++j)
      coordinates += basis(j, k) * out.loop_periods.row(j).transpose().cwiseQuotient(
                                       loop_sign.cast<std::complex<double>>());
    const Eigen::VectorXcd periods = basis_inverse.cast<std::complex<double>>() * coordinates;
    out.a_periods.row(k) = periods.head(g).transpose();
    out.b_periods.row(k) = periods.tail(g).transpose();
  }
  out.riemann_matrix = out.a_periods.inverse() * out.b_periods;
  if (out.riemann_matrix.imag().trace() < 0) { // the opposite orientation convention: b -> -b
    out.b_periods = -out.b_periods;
    out.riemann_matrix = -out.riemann_matrix;
  }
  if (g == 1) out.modulus = reduce_modulus(out.riemann_matrix(0, 0));

  return basis;
}

// Edge values of the normalized psi = A^-1 phi, phi_k = sum_j P_jk tau_j, on the mesh's edges.
// With tau_j = h_j + i sum_l C_jl h_l: psi = D h with D = c (1 + i C), c = A^-1 P^T (P: the
// basis' first g columns), one pass over the edges per (m, l) pair.
void normalized_forms(const Eigen::MatrixXd &basis, HolomorphicForms &out) {
  const int n = 2 * out.genus, g = out.genus;
  const Eigen::MatrixXcd c =
      out.a_periods.inverse() * basis.leftCols(g).transpose().cast<std::complex<double>>();
  const Eigen::MatrixXcd d =
      c + std::complex<double>(0, 1) * c * out.conjugate.cast<std::complex<double>>();
  const long edge_count = out.harmonic.front().size();
  out.normalized.resize(size_t(g));
  parallel_for( // the forms over the cores
      size_t(g),
      [&](size_t m) {
        Eigen::VectorXcd psi = Eigen::VectorXcd::Zero(edge_count);
        for (int l = 0; l < n; ++l) {
          psi.real() += d(long(m), l).real() * out.harmonic[size_t(l)];
          psi.imag() += d(long(m), l).imag() * out.harmonic[size_t(l)];
        }
        out.normalized[m] = out.intrinsic->integrate_along_mesh_edges(psi);
      },
      2);
}

// The area-weighted mean and the largest |g| / |f| of phi_1 over the faces.
void measure_non_holomorphicity(const FaceCorners &faces, const MeshEdges &edges,
                                const FaceGeometry &geometry, const Eigen::MatrixXd &basis,
                                HolomorphicForms &out) {
  // phi_1 = sum_j P_j1 (h_j + i sum_l C_jl h_l): its real and imaginary parts as edge values.
  const Eigen::VectorXd first = basis.col(0), imaginary = out.conjugate.transpose() * first;
  Eigen::VectorXcd form = Eigen::VectorXcd::Zero(out.harmonic.front().size());
  for (size_t j = 0; j < out.harmonic.size(); ++j)
    form += std::complex<double>(first[long(j)], imaginary[long(j)]) * out.harmonic[j];
  const LocalCoefficients local = local_coefficients(faces, edges, geometry, form);
  double weighted = 0, total_area = 0;
  for (size_t f = 0; f < local.f.size(); ++f) {
    const double ratio = std::abs(local.g[f]) / std::abs(local.f[f]);
    weighted += geometry.areas[f] * ratio;
    total_area += geometry.areas[f];
    out.non_holomorphicity_max = std::max(out.non_holomorphicity_max, ratio);
  }
  out.non_holomorphicity_mean = weighted / total_area;
}

HolomorphicForms forms_of(const Mesh &input, SolverKind solver, const Progress &progress,
                          const Validation *validated) {
  const Validation validation = validated ? *validated : validate_mesh(input);
  if (!validation.ok()) throw refusal(validation.main_finding());
  // Computed at unit scale (unit_scale.h): the forms' values on edges do not depend on it.
  Mesh unit;
  const bool copy = !is_at_unit_scale(input);
  if (copy) copy_at_unit_scale(input, unit_scale_of(input), unit);
  const auto start = std::chrono::steady_clock::now();
  progress.report(0.0, "edges and cotangent weights");
  const PreparedMesh prepared = prepare_mesh(copy ? unit : input);
  const double preparing_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  HolomorphicForms out = compute_holomorphic_forms(prepared, solver, progress);
  out.notes = validation.notes;
  out.timings_ms.front().second += preparing_ms; // "laplacian": edges and weights too
  return out;
}

} // namespace

HolomorphicForms compute_holomorphic_forms(const Mesh &input, SolverKind solver,
                                           const Progress &progress, const Validation *validated) {
  // The job runs on a worker thread; the callback is called on this one, steadily.
  HolomorphicForms out;
  run_reporting(progress, [&](const Progress &relay) {
    const JobThreads threads; // the team for this job's loops: common/job_threads.h
    out = forms_of(input, solver, relay, validated);
  });
  return out;
}

HolomorphicForms compute_holomorphic_forms(const PreparedMesh &prepared, SolverKind solver,
                                           const Progress &progress) {
  const Mesh &mesh = prepared.mesh;
  HolomorphicForms out;
  StageClock clock(out.timings_ms);
  const int vertex_count = int(mesh.vert.size());

  out.genus = (2 - (vertex_count - prepared.edges.edge_count() + int(mesh.face.size()))) / 2;
  if (out.genus == 0) {
    clock.done("laplacian");
    return out; // no forms: nothing to factor
  }
  // The forms live on the intrinsic Delaunay triangulation (non-negative weights), and are taken
  // back to the mesh's edges at the end.
  out.intrinsic = std::make_shared<IntrinsicDelaunay>(mesh, prepared.edges);
  const MeshEdges &edges = out.intrinsic->edges();
  const std::vector<double> weights = out.intrinsic->cotan_weights();
  clock.done("laplacian");

  progress.report(0.1, "homology basis");
  out.homology = tree_cotree(vertex_count, edges);
  clock.done("homology");

  progress.report(0.2, "factoring the Laplacian");
  std::unique_ptr<LaplacianSolver> factored =
      factor_laplacian(cotan_laplacian(vertex_count, edges, weights), solver);
  clock.done("factorization");

  progress.report(0.6, "harmonic forms");
  // The factor, the largest array here, is released inside once solved: nothing below solves.
  out.harmonic =
      harmonic_forms(out.homology.dual_forms, vertex_count, edges, weights, std::move(factored));
  clock.done("harmonic");

  progress.report(0.8, "holomorphic forms and periods");
  measure_residuals(vertex_count, edges, weights, out);
  Eigen::MatrixXd basis;
  {
    // Laid out only now, the factor (the largest array) gone, and freed before the normalized
    // forms are laid out on the edges.
    const FaceCorners faces = out.intrinsic->laid_out_flat();
    const FaceGeometry geometry = face_geometry(faces);
    const ConjugateFit fit = conjugate_coefficients(faces, edges, geometry, out.harmonic);
    out.conjugate = fit.coefficients;
    out.conjugate_residual = fit.relative_residual;
    basis = canonical_periods(fit.intersections, out);
    measure_non_holomorphicity(faces, edges, geometry, basis, out);
  }
  normalized_forms(basis, out);
  clock.done("holomorphic");
  progress.report(1.0, "done");
  return out;
}

void release_intermediates(HolomorphicForms &forms) {
  forms.intrinsic.reset();
  forms.homology = {};
  forms.harmonic = {};
}

} // namespace meromorph
