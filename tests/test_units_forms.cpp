// Direct tests of the forms on a grid torus: harmonic and conjugate forms, local coefficients,
// periods and the symplectic basis.
#include "stage_units.h"

namespace meromorph {
namespace {

using namespace test;

struct TorusForms {
  Mesh mesh;
  std::unique_ptr<PreparedMesh> prepared;
  HomologyBasis homology;
  std::vector<Eigen::VectorXd> harmonic;
};

void torus_forms(TorusForms &out, int segments = 48) {
  make_grid_torus(out.mesh, 2.0, 1.0, segments, segments / 2);
  out.prepared = std::make_unique<PreparedMesh>(prepare_mesh(out.mesh));
  const int n = int(out.mesh.vert.size());
  out.homology = tree_cotree(n, out.prepared->edges);
  out.harmonic = harmonic_forms(
      out.homology.dual_forms, n, out.prepared->edges, out.prepared->weights,
      factor_laplacian(cotan_laplacian(n, out.prepared->edges, out.prepared->weights)));
}

TEST(HarmonicForms, CoClosedClosedAndWithTheSamePeriods) {
  TorusForms torus;
  torus_forms(torus);
  const MeshEdges &edges = torus.prepared->edges;
  ASSERT_EQ(torus.harmonic.size(), 2u);
  for (size_t j = 0; j < 2; ++j) {
    const Eigen::VectorXd &h = torus.harmonic[j], &omega = torus.homology.dual_forms[j];
    const Eigen::VectorXd divergence =
        weighted_divergence(int(torus.mesh.vert.size()), edges, torus.prepared->weights, h);
    EXPECT_LT(divergence.cwiseAbs().maxCoeff(), 1e-9 * h.cwiseAbs().maxCoeff());
    for (size_t f = 0; f < edges.face_edges.size(); ++f) {
      double sum = 0;
      for (int k = 0; k < 3; ++k)
        sum += edges.face_signs[f][k] * h[edges.face_edges[f][k]];
      ASSERT_LT(std::abs(sum), 1e-12) << "face " << f;
    }
    for (const auto &loop : torus.homology.primal_loops)
      EXPECT_NEAR(integrate(h, loop), integrate(omega, loop), 1e-12);
  }
}

TEST(HolomorphicForms, TheConjugateSquaredIsMinusOneInTheLimit) {
  // The Hodge star of a torus's harmonic forms squares to -1: the discrete C^2 + 1 goes to zero
  // in the square of the edge length, the fit's residual in the edge length (measured: 2.7e-2,
  // 6.8e-3, 1.7e-3 and 0.137, 0.069, 0.035 at 24, 48, 96 segments).
  double previous_residual = 0, previous_error = 0;
  for (int segments : {24, 48, 96}) {
    TorusForms torus;
    torus_forms(torus, segments);
    std::vector<Eigen::MatrixX3d> vectors;
    for (const Eigen::VectorXd &h : torus.harmonic)
      vectors.push_back(
          face_vectors(torus.mesh, torus.prepared->edges, torus.prepared->geometry, h));
    const ConjugateFit fit = conjugate_coefficients(vectors, torus.prepared->geometry);
    const Eigen::MatrixXd square = fit.coefficients * fit.coefficients;
    const double error = (square + Eigen::MatrixXd::Identity(2, 2)).norm();
    EXPECT_LT(error, 0.03) << segments << "\n" << square;
    if (previous_residual > 0) {
      EXPECT_LT(fit.relative_residual, 0.6 * previous_residual) << segments;
      EXPECT_LT(error, 0.3 * previous_error) << segments;
    }
    previous_residual = fit.relative_residual;
    previous_error = error;
  }
}

TEST(HolomorphicForms, LocalCoefficientsOfDzAndDzBar) {
  MeshArrays arrays;
  arrays.positions = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0.3, 0.8, 0)};
  arrays.triangles = {{0, 1, 2}};
  Mesh triangle;
  mesh_from_arrays(arrays, triangle);
  const FaceGeometry geometry = face_geometry(triangle);
  Eigen::MatrixX3d dx(1, 3), dy(1, 3), minus_dy(1, 3);
  dx << 1, 0, 0;
  dy << 0, 1, 0;
  minus_dy << 0, -1, 0;
  const LocalCoefficients dz = local_coefficients(geometry, dx, dy);
  EXPECT_NEAR(std::abs(dz.f[0]), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(dz.g[0]), 0.0, 1e-12);
  const LocalCoefficients dzbar = local_coefficients(geometry, dx, minus_dy);
  EXPECT_NEAR(std::abs(dzbar.f[0]), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(dzbar.g[0]), 1.0, 1e-12);
}

// Several forms' dz coefficients in one pass are the ones computed form by form, to the bit; a
// pair's, combined from the normalized forms' (ratio_dz), are those of the pair's forms
// (ratio_forms) to rounding; and the mesh prepared in two steps (edges first, the rest after the
// forms) is the mesh prepared at once.
TEST(HolomorphicForms, DzCoefficientsInOnePassAndTwoStepPreparationMatchTheSingleOnes) {
  Mesh mesh;
  make_genus_surface(mesh, 3, 12);
  const PreparedMesh prepared = prepare_mesh(mesh);
  std::vector<Eigen::VectorXcd> forms;
  for (int k = 0; k < 3; ++k)
    forms.push_back(Eigen::VectorXcd::Random(prepared.edges.edge_count()));
  const Eigen::MatrixXcd dz = dz_coefficients(mesh, prepared.edges, prepared.geometry, forms);
  ASSERT_EQ(dz.rows(), 3);
  ASSERT_EQ(size_t(dz.cols()), mesh.face.size());
  for (int k = 0; k < 3; ++k) {
    const std::vector<Complex> single =
        local_coefficients(mesh, prepared.edges, prepared.geometry, forms[size_t(k)]).f;
    for (size_t f = 0; f < single.size(); ++f)
      ASSERT_EQ(dz(k, long(f)), single[f]) << "form " << k << ", face " << f;
  }
  for (const FormPair &pair : generic_form_pairs(3)) {
    const std::array<Eigen::VectorXcd, 2> edge_forms = ratio_forms(pair, forms);
    const Eigen::MatrixXcd direct =
        dz_coefficients(mesh, prepared.edges, prepared.geometry, {edge_forms[0], edge_forms[1]});
    const std::array<std::vector<Complex>, 2> combined = ratio_dz(pair, dz);
    for (long side = 0; side < 2; ++side)
      for (size_t f = 0; f < combined[0].size(); ++f)
        ASSERT_NEAR(std::abs(combined[size_t(side)][f] - direct(side, long(f))), 0.0,
                    1e-12 * (1 + std::abs(direct(side, long(f)))))
            << "side " << side << ", face " << f;
  }

  PreparedMesh stepwise = prepare_mesh_edges(mesh);
  EXPECT_TRUE(stepwise.incidence.corners.empty() && stepwise.weights.empty());
  prepare_the_rest(stepwise);
  EXPECT_EQ(stepwise.edges.vertices, prepared.edges.vertices);
  EXPECT_EQ(stepwise.edges.face_signs, prepared.edges.face_signs);
  EXPECT_EQ(stepwise.weights, prepared.weights);
  EXPECT_EQ(stepwise.incidence.corners, prepared.incidence.corners);
  EXPECT_EQ(stepwise.incidence.faces_of_vertex.items, prepared.incidence.faces_of_vertex.items);
  EXPECT_EQ(stepwise.edges_at_vertex.items, prepared.edges_at_vertex.items);
  EXPECT_EQ(stepwise.geometry.areas, prepared.geometry.areas);
  EXPECT_EQ(stepwise.vertex_areas, prepared.vertex_areas);
}

TEST(Periods, ModulusReductionAndSymplecticBasis) {
  // 2.3 + 0.5i: less 2, then -1/tau (its modulus is below 1), then plus 1.
  const std::complex<double> reduced = reduce_modulus({2.3, 0.5});
  EXPECT_NEAR(reduced.real(), 1.0 - 0.3 / 0.34, 1e-12);
  EXPECT_NEAR(reduced.imag(), 0.5 / 0.34, 1e-12);
  EXPECT_NEAR(std::abs(reduce_modulus({0, 0.5}) - std::complex<double>(0, 2)), 0, 1e-12);
  EXPECT_NEAR(std::abs(reduce_modulus({0, 1}) - std::complex<double>(0, 1)), 0, 1e-12);
  // W = Q^T J Q for a unimodular Q: P^T W P = J.
  Eigen::MatrixXi J = Eigen::MatrixXi::Zero(4, 4);
  J.topRightCorner(2, 2) = Eigen::MatrixXi::Identity(2, 2);
  J.bottomLeftCorner(2, 2) = -Eigen::MatrixXi::Identity(2, 2);
  Eigen::MatrixXi Q(4, 4);
  Q << 1, 2, 0, 1, 0, 1, 3, 0, 0, 0, 1, 0, 1, 2, 0, 2;
  const Eigen::MatrixXi W = Q.transpose() * J * Q;
  const Eigen::MatrixXi P = symplectic_basis(W);
  EXPECT_EQ(P.transpose() * W * P, J);
  EXPECT_EQ(std::abs(std::lround(P.cast<double>().determinant())), 1);
  // The torus's two loops meet once.
  TorusForms torus;
  torus_forms(torus);
  std::vector<Eigen::VectorXd> dual_forms;
  for (const Eigen::SparseVector<double> &omega : torus.homology.dual_forms)
    dual_forms.push_back(Eigen::VectorXd(omega));
  const Eigen::MatrixXi wedge = wedge_matrix(dual_forms, torus.prepared->edges);
  EXPECT_EQ(wedge(0, 0), 0);
  EXPECT_EQ(std::abs(wedge(0, 1)), 1);
  EXPECT_EQ(wedge(1, 0), -wedge(0, 1));
}

} // namespace
} // namespace meromorph
