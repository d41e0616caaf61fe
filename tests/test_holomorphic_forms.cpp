// Holomorphic 1-forms against exact results: torus moduli, Riemann's bilinear relations,
// closedness, co-closedness, the symplectic basis, invariance, and the two solvers.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "common/errors.h"
#include "forms/holomorphic_pipeline.h"
#include "mesh/cotan_laplacian.h"
#include "mesh/mesh_edges.h"
#include "shapes/generated_surfaces.h"
#include "shapes/rigid_motion.h"
#include "test_support.h"

namespace meromorph {
namespace {

double modulus_error(const HolomorphicForms &forms, double R, double r) {
  const std::complex<double> exact(0.0, std::sqrt(R * R - r * r) / r);
  return std::abs(*forms.modulus - exact) / std::abs(exact);
}

TEST(HolomorphicForms, TorusModulusConvergesToTheExactValue) {
  for (auto [R, r] : {std::pair{2.0, 1.0}, std::pair{3.0, 1.0}}) {
    double previous = 1.0;
    for (int resolution : {16, 32, 64}) {
      Mesh mesh;
      make_grid_torus(mesh, R, r, int(std::lround(resolution * R / r)), resolution);
      const HolomorphicForms forms = compute_holomorphic_forms(mesh);
      ASSERT_EQ(forms.genus, 1);
      ASSERT_TRUE(forms.modulus.has_value());
      const double error = modulus_error(forms, R, r);
      EXPECT_LT(error, previous) << "R=" << R << " resolution " << resolution;
      previous = error;
    }
    // About 20k vertices.
    const int resolution = R == 2.0 ? 100 : 82;
    Mesh mesh;
    make_grid_torus(mesh, R, r, int(std::lround(resolution * R / r)), resolution);
    EXPECT_NEAR(mesh.VN(), 20000, 500);
    EXPECT_LT(modulus_error(compute_holomorphic_forms(mesh), R, r), 0.005) << "R=" << R;
  }
}

TEST(HolomorphicForms, TwoTriangulationsOfOneTorusAgree) {
  Mesh grid, implicit;
  make_grid_torus(grid, 2.0, 1.0, 96, 48);
  make_implicit_torus(implicit, 2.0, 1.0, 48);
  const auto a = *compute_holomorphic_forms(grid).modulus;
  const auto b = *compute_holomorphic_forms(implicit).modulus;
  EXPECT_LT(std::abs(a - b) / std::abs(a), 0.01) << a << " vs " << b;
}

void expect_riemann_relations(const HolomorphicForms &forms, const std::string &name) {
  const Eigen::MatrixXcd &omega = forms.riemann_matrix;
  ASSERT_EQ(omega.rows(), forms.genus) << name;
  EXPECT_LT((omega - omega.transpose()).norm(), 0.01 * omega.norm()) << name << "\n" << omega;
  const Eigen::MatrixXd imaginary = omega.imag();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(0.5 *
                                                             (imaginary + imaginary.transpose()));
  EXPECT_GT(eigen.eigenvalues().minCoeff(), 0.0) << name << "\n" << omega;
}

void expect_exact_structure(const Mesh &mesh, const HolomorphicForms &forms,
                            const std::string &name) {
  // Closed forms close on every face of the triangulation they live on (the intrinsic Delaunay
  // one); harmonic forms are co-closed to the solver's precision.
  ASSERT_TRUE(forms.intrinsic) << name;
  const MeshEdges &intrinsic = forms.intrinsic->edges();
  for (const Eigen::SparseVector<double> &crossings : forms.homology.dual_forms) {
    const Eigen::VectorXd omega(crossings);
    for (size_t f = 0; f < intrinsic.face_edges.size(); ++f) {
      double sum = 0;
      for (int k = 0; k < 3; ++k)
        sum += intrinsic.face_signs[f][k] * omega[intrinsic.face_edges[f][k]];
      ASSERT_LE(std::abs(sum), 1e-12) << name << " face " << f;
    }
  }
  // Taken to the mesh's edges along homotopic paths, the normalized forms close on every face of
  // the mesh too.
  const MeshEdges edges = build_mesh_edges(mesh);
  for (const Eigen::VectorXcd &psi : forms.normalized) {
    double scale = psi.cwiseAbs().maxCoeff(), worst = 0;
    for (size_t f = 0; f < edges.face_edges.size(); ++f) {
      std::complex<double> sum = 0;
      for (int k = 0; k < 3; ++k)
        sum += double(edges.face_signs[f][k]) * psi[edges.face_edges[f][k]];
      worst = std::max(worst, std::abs(sum));
    }
    EXPECT_LE(worst, 1e-9 * scale) << name;
  }
  EXPECT_LE(forms.closedness_residual, 1e-12) << name;
  EXPECT_LE(forms.coclosedness_residual, 1e-9) << name;
  // Loop i meets dual loop j iff i = j.
  const int n = 2 * forms.genus;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      EXPECT_EQ(std::abs(integrate(forms.homology.dual_forms[j], forms.homology.primal_loops[i])),
                i == j ? 1.0 : 0.0)
          << name;
  // The canonical basis is symplectic.
  Eigen::MatrixXi J = Eigen::MatrixXi::Zero(n, n);
  J.topRightCorner(forms.genus, forms.genus) = Eigen::MatrixXi::Identity(forms.genus, forms.genus);
  J.bottomLeftCorner(forms.genus, forms.genus) =
      -Eigen::MatrixXi::Identity(forms.genus, forms.genus);
  EXPECT_EQ(forms.symplectic.transpose() * forms.wedge * forms.symplectic, J) << name;
  EXPECT_LE(forms.wedge_rounding, 1e-9) << name;
  // The intersection numbers (summed from two sides per face in the conjugate fit's pass) are
  // Whitney's integrals of h_j ^ h_k over every side of every face, to rounding.
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) {
      const Eigen::VectorXd &a = forms.harmonic[size_t(j)], &b = forms.harmonic[size_t(k)];
      double integral = 0;
      for (size_t f = 0; f < intrinsic.face_edges.size(); ++f)
        for (int side = 0; side < 3; ++side) {
          const int next = (side + 1) % 3;
          const double a_side = intrinsic.face_signs[f][side] * a[intrinsic.face_edges[f][side]];
          const double b_side = intrinsic.face_signs[f][side] * b[intrinsic.face_edges[f][side]];
          const double a_next = intrinsic.face_signs[f][next] * a[intrinsic.face_edges[f][next]];
          const double b_next = intrinsic.face_signs[f][next] * b[intrinsic.face_edges[f][next]];
          integral += (a_side * b_next - a_next * b_side) / 6.0;
        }
      EXPECT_EQ(forms.wedge(j, k), std::lround(integral)) << name << " " << j << " " << k;
      EXPECT_NEAR(integral, std::round(integral), 1e-9) << name << " " << j << " " << k;
    }
}

TEST(HolomorphicForms, RiemannMatrixOfGenusTwoAndThree) {
  for (int genus : {2, 3}) {
    Mesh mesh;
    make_genus_surface(mesh, genus, 24);
    const HolomorphicForms forms = compute_holomorphic_forms(mesh);
    EXPECT_EQ(forms.genus, genus);
    expect_exact_structure(mesh, forms, "genus " + std::to_string(genus));
    expect_riemann_relations(forms, "genus " + std::to_string(genus));
  }
  Mesh eight;
  test::load(test::data_path("eight.off"), eight);
  const HolomorphicForms forms = compute_holomorphic_forms(eight);
  EXPECT_EQ(forms.genus, 2);
  expect_exact_structure(eight, forms, "eight.off");
  expect_riemann_relations(forms, "eight.off");
}

TEST(HolomorphicForms, RawMarchingCubesTrianglesDoNotBreakIt) {
  Mesh mesh;
  make_genus_surface(mesh, 2, 24, false);
  const HolomorphicForms forms = compute_holomorphic_forms(mesh);
  expect_exact_structure(mesh, forms, "raw marching cubes");
  expect_riemann_relations(forms, "raw marching cubes");
  // Its obtuse triangles give negative cotangent weights; the intrinsic Delaunay triangulation
  // the forms are computed on has none.
  const std::vector<double> mesh_weights = cotan_weights(mesh, build_mesh_edges(mesh));
  EXPECT_LT(*std::min_element(mesh_weights.begin(), mesh_weights.end()), -0.1);
  EXPECT_GT(forms.intrinsic->flips(), 0);
  const std::vector<double> weights = forms.intrinsic->cotan_weights();
  EXPECT_GE(*std::min_element(weights.begin(), weights.end()), -1e-9);
}

TEST(HolomorphicForms, ModulusOfANeedleTorusMatchesTheExactValue) {
  // The implicit torus by raw marching cubes (needles and caps): the exact modulus
  // i sqrt(R^2 - r^2) / r holds on the intrinsic Delaunay triangulation as on clean meshes.
  Mesh mesh;
  make_implicit_torus(mesh, 2.0, 1.0, 48, false);
  const HolomorphicForms forms = compute_holomorphic_forms(mesh);
  ASSERT_TRUE(forms.modulus);
  const std::complex<double> exact(0, std::sqrt(3.0));
  EXPECT_LT(std::abs(*forms.modulus - exact), 0.01 * std::abs(exact)) << *forms.modulus;
}

TEST(HolomorphicForms, InvariantUnderRigidMotionAndScale) {
  Mesh torus, genus2;
  make_grid_torus(torus, 3.0, 1.0, 60, 20);
  make_genus_surface(genus2, 2, 20);
  for (Mesh *mesh : {&torus, &genus2}) {
    const HolomorphicForms before = compute_holomorphic_forms(*mesh);
    Similarity motion = random_rigid_motion(7);
    motion.scale = 3.7;
    apply_similarity(motion, *mesh);
    const HolomorphicForms after = compute_holomorphic_forms(*mesh);
    EXPECT_LT((after.riemann_matrix - before.riemann_matrix).norm(),
              1e-6 * before.riemann_matrix.norm());
    if (before.modulus) {
      EXPECT_LT(std::abs(*after.modulus - *before.modulus), 1e-6 * std::abs(*before.modulus));
    }
  }
}

TEST(HolomorphicForms, CholmodAndSimplicialLdltAgree) {
  Mesh mesh;
  make_genus_surface(mesh, 2, 20);
  const HolomorphicForms cholmod = compute_holomorphic_forms(mesh, SolverKind::cholmod);
  const HolomorphicForms ldlt = compute_holomorphic_forms(mesh, SolverKind::eigen_ldlt);
  for (size_t j = 0; j < cholmod.harmonic.size(); ++j)
    EXPECT_LT((cholmod.harmonic[j] - ldlt.harmonic[j]).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((cholmod.riemann_matrix - ldlt.riemann_matrix).norm(), 1e-9);
}

TEST(HolomorphicForms, RefusesWhatValidationRefuses) {
  Mesh open;
  test::load(test::data_path("eight.hole.off"), open);
  EXPECT_THROW(compute_holomorphic_forms(open), InputError);
}

} // namespace
} // namespace meromorph
