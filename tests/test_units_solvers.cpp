// Direct tests of the linear solvers on systems whose answer is known: CHOLMOD and Eigen's
// factorizations of pinned Laplacians, orders, leading blocks, reweighting, the clusters'
// preconditioner and conjugate gradients that pause and go on.
#include "stage_units.h"

namespace meromorph {
namespace {

using namespace test;

// The cotangent Laplacian of an icosphere (three subdivisions), for the solver tests.
struct IcosphereLaplacian {
  Mesh mesh;
  std::unique_ptr<PreparedMesh> prepared;
  Eigen::SparseMatrix<double> laplacian;
  int n = 0;
  IcosphereLaplacian() {
    make_icosphere(mesh, 3);
    prepared = std::make_unique<PreparedMesh>(prepare_mesh(mesh));
    n = int(mesh.vert.size());
    laplacian = cotan_laplacian(n, prepared->edges, prepared->weights);
  }
};

TEST(LaplacianSolver, BothFactorizationsSolveThePinnedSystem) {
  EXPECT_EQ(solver_from_name("cholmod"), SolverKind::cholmod);
  EXPECT_EQ(solver_from_name("ldlt"), SolverKind::eigen_ldlt);
  EXPECT_STREQ(solver_name(SolverKind::eigen_ldlt), "ldlt");
  const IcosphereLaplacian sphere;
  const Mesh &mesh = sphere.mesh;
  const int n = sphere.n;
  const Eigen::SparseMatrix<double> &laplacian = sphere.laplacian;
  Eigen::VectorXd expected(n);
  for (int v = 0; v < n; ++v)
    expected[v] = std::sin(3.0 * mesh.vert[size_t(v)].cP()[0]) + mesh.vert[size_t(v)].cP()[2];
  expected.array() -= expected[0]; // vertex 0 pinned at 0
  const Eigen::VectorXd right = laplacian * expected;
  for (SolverKind kind : {SolverKind::cholmod, SolverKind::eigen_ldlt}) {
    const Eigen::VectorXd solved = factor_laplacian(laplacian, kind)->solve(right);
    EXPECT_LT((solved - expected).cwiseAbs().maxCoeff(), 1e-8) << solver_name(kind);
  }
  // A Dirichlet problem: the pinned values are the caller's, put into the right-hand side.
  const std::vector<int> pinned = {0, 5, 17};
  Eigen::VectorXd boundary = Eigen::VectorXd::Zero(n);
  for (int v : pinned)
    boundary[v] = expected[v] + 1.0;
  Eigen::VectorXd with_boundary = expected;
  for (int v : pinned)
    with_boundary[v] = boundary[v];
  Eigen::VectorXd rhs = laplacian * with_boundary - laplacian * boundary;
  for (int v : pinned)
    rhs[v] = 0;
  const Eigen::VectorXd free = factor_laplacian(laplacian, SolverKind::cholmod, pinned)->solve(rhs);
  for (int v = 0; v < n; ++v) {
    if (std::find(pinned.begin(), pinned.end(), v) == pinned.end()) {
      EXPECT_NEAR(free[v], with_boundary[v], 1e-8) << v;
    }
  }
}

// A Hermitian positive definite system on a grid of side `side`: unit couplings rotated by a
// phase to each right and upper neighbour, `stiff` between every third unknown and the next one
// (a needle's short side), `held` between that one and the next (a needle's far corner), a
// diagonal that dominates: its unit couplings are below cluster_coupling.
Eigen::SparseMatrix<Complex> grid_system(int side, double stiff, double held = 1.0) {
  const int n = side * side;
  std::vector<Eigen::Triplet<Complex>> entries;
  Eigen::VectorXd diagonal = Eigen::VectorXd::Constant(n, 5.0); // unit couplings below 0.15
  auto couple = [&](int i, int j, double weight, double phase) {
    const Complex value = -weight * std::polar(1.0, phase);
    entries.emplace_back(i, j, value);
    entries.emplace_back(j, i, std::conj(value));
    diagonal[i] += weight;
    diagonal[j] += weight;
  };
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const int i = x + side * y;
      if (x + 1 < side) couple(i, i + 1, x % 3 == 0 ? stiff : x % 3 == 1 ? held : 1.0, 0.3);
      if (y + 1 < side) couple(i, i + side, 1.0, -0.7);
    }
  for (int i = 0; i < n; ++i)
    entries.emplace_back(i, i, diagonal[i]);
  Eigen::SparseMatrix<Complex> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  a.makeCompressed();
  return a;
}

CompressedColumns columns_of(const Eigen::SparseMatrix<Complex> &a) {
  return {int(a.rows()), a.outerIndexPtr(), a.innerIndexPtr(), a.valuePtr()};
}

// A right-hand side of no particular shape.
Eigen::VectorXcd wavy_right(long size) {
  Eigen::VectorXcd right(size);
  for (long i = 0; i < size; ++i)
    right[i] = Complex(std::sin(0.1 * double(i)), std::cos(0.37 * double(i)));
  return right;
}

// x with a x = right, by a sparse Cholesky factorization.
Eigen::VectorXcd solved_directly(const Eigen::SparseMatrix<Complex> &a,
                                 const Eigen::VectorXcd &right) {
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<Complex>> direct(a);
  EXPECT_EQ(direct.info(), Eigen::Success);
  return direct.solve(right);
}

// Stiff pairs: the clusters' preconditioner converges in a fraction of Jacobi's steps, to the
// direct solution; without them the system is not called stiff.
TEST(ClusterJacobi, StiffPairsConvergeInAFractionOfJacobisSteps) {
  const Eigen::SparseMatrix<Complex> stiff = grid_system(60, 1e4), plain = grid_system(60, 1.0);
  EXPECT_TRUE(stiffly_coupled(columns_of(stiff)));
  EXPECT_FALSE(stiffly_coupled(columns_of(plain)));
  const Eigen::VectorXcd right = wavy_right(stiff.rows());
  const Eigen::VectorXcd expected = solved_directly(stiff, right);
  Eigen::ConjugateGradient<Eigen::SparseMatrix<Complex>, Eigen::Lower | Eigen::Upper> jacobi;
  Eigen::ConjugateGradient<Eigen::SparseMatrix<Complex>, Eigen::Lower | Eigen::Upper, ClusterJacobi>
      clustered;
  jacobi.setTolerance(1e-10);
  clustered.setTolerance(1e-10);
  jacobi.compute(stiff);
  clustered.compute(stiff);
  const Eigen::VectorXcd by_jacobi = jacobi.solve(right), by_clusters = clustered.solve(right);
  ASSERT_EQ(jacobi.info(), Eigen::Success);
  ASSERT_EQ(clustered.info(), Eigen::Success);
  EXPECT_LT((by_clusters - expected).norm(), 1e-8 * expected.norm());
  EXPECT_LT((by_jacobi - expected).norm(), 1e-8 * expected.norm());
  EXPECT_LT(clustered.iterations() * 4, jacobi.iterations())
      << clustered.iterations() << " against " << jacobi.iterations();
  // Every third unknown and its right neighbour: 1200 pairs and 1200 alone.
  EXPECT_EQ(clustered.preconditioner().cluster_count(), 2400);
  // From the lower triangle alone (as the charts hold their matrices): the same clusters, steps
  // and solution.
  const Eigen::SparseMatrix<Complex> lower = stiff.triangularView<Eigen::Lower>();
  Eigen::ConjugateGradient<Eigen::SparseMatrix<Complex>, Eigen::Lower, ClusterJacobi> from_lower;
  from_lower.setTolerance(1e-10);
  from_lower.compute(lower);
  const Eigen::VectorXcd by_lower = from_lower.solve(right);
  ASSERT_EQ(from_lower.info(), Eigen::Success);
  EXPECT_EQ(from_lower.preconditioner().cluster_count(), 2400);
  EXPECT_EQ(from_lower.iterations(), clustered.iterations());
  EXPECT_LT((by_lower - expected).norm(), 1e-8 * expected.norm());
}

// The charts' conjugate gradients (solvers/hermitian_cg.h), from the lower triangle of a stiff
// system: to the direct solution with either preconditioner, the clusters in a fraction of the
// diagonal's steps; stopped at 1e-3 and gone on to 1e-10, the same steps and the same solution
// to the bit as in one pass, and the residual of each pass within its tolerance.
TEST(HermitianConjugateGradients, PausedAndResumedAsIfInOnePass) {
  const Eigen::SparseMatrix<Complex> stiff = grid_system(60, 1e4);
  const Eigen::SparseMatrix<Complex> lower = stiff.triangularView<Eigen::Lower>();
  const Eigen::VectorXcd right = wavy_right(stiff.rows());
  const Eigen::VectorXcd expected = solved_directly(stiff, right);
  const Eigen::VectorXcd start = Eigen::VectorXcd::Zero(stiff.rows());
  using Kind = HermitianConjugateGradients::Preconditioner;
  // (the solver takes its matrix over)
  auto copy_of = [](const Eigen::SparseMatrix<Complex> &matrix) { return matrix; };
  HermitianConjugateGradients once(copy_of(lower), right, start, Kind::clusters);
  HermitianConjugateGradients diagonal(copy_of(lower), right, start, Kind::diagonal);
  ASSERT_TRUE(once.advance(1e-10, 100000));
  ASSERT_TRUE(diagonal.advance(1e-10, 100000));
  EXPECT_LT((once.solution() - expected).norm(), 1e-8 * expected.norm());
  EXPECT_LT((diagonal.solution() - expected).norm(), 1e-8 * expected.norm());
  EXPECT_LT(once.steps() * 4, diagonal.steps()) << once.steps() << " against " << diagonal.steps();
  HermitianConjugateGradients twice(copy_of(lower), right, start, Kind::clusters);
  ASSERT_TRUE(twice.advance(1e-3, 100000));
  const int screening_steps = twice.steps();
  EXPECT_LE((right - stiff * twice.solution()).norm(), 1e-3 * right.norm());
  EXPECT_GT((twice.solution() - expected).norm(), 1e-6 * expected.norm()) << "stopped early";
  ASSERT_TRUE(twice.advance(1e-10, 100000));
  EXPECT_LT(screening_steps, twice.steps());
  EXPECT_EQ(twice.steps(), once.steps());
  EXPECT_TRUE(twice.solution() == once.solution());
  EXPECT_LE((right - stiff * twice.solution()).norm(), 1e-10 * right.norm() * 1.01);
  // Too few steps allowed: not converged, and told so.
  HermitianConjugateGradients short_of_steps(copy_of(lower), right, start, Kind::diagonal);
  EXPECT_FALSE(short_of_steps.advance(1e-10, 3));
  EXPECT_EQ(short_of_steps.steps(), 3);
}

// An unknown whose diagonal comes mostly from its coupling to one of a stiff pair (its coupling
// small beside the pair's diagonals, |a_ij| / sqrt(a_ii a_jj) = 0.07) joins the pair's cluster:
// three unknowns move as one there.
TEST(ClusterJacobi, AnUnknownHeldByAStiffPairJoinsItsCluster) {
  const Eigen::SparseMatrix<Complex> held = grid_system(60, 1e4, 50.0);
  ClusterJacobi clusters;
  clusters.compute(held);
  // Every third unknown, its right neighbour and the one after that: 1200 triples.
  EXPECT_EQ(clusters.cluster_count(), 1200);
  const Eigen::VectorXcd right = wavy_right(held.rows());
  const Eigen::VectorXcd expected = solved_directly(held, right);
  Eigen::ConjugateGradient<Eigen::SparseMatrix<Complex>, Eigen::Lower | Eigen::Upper, ClusterJacobi>
      clustered;
  clustered.setTolerance(1e-10);
  clustered.compute(held);
  const Eigen::VectorXcd solved = clustered.solve(right);
  ASSERT_EQ(clustered.info(), Eigen::Success);
  EXPECT_LT((solved - expected).norm(), 1e-8 * expected.norm());
}

// A matrix made of stiff clusters alone is its own preconditioner: one step solves it. Clusters
// hold at most cluster_size unknowns (a chain of 20 comes in two).
TEST(ClusterJacobi, ClustersOfAtMostSixteenAndABlockMatrixInOneStep) {
  std::vector<Eigen::Triplet<Complex>> entries;
  int n = 0;
  for (int size : {2, 3, 5, 8, 1, 4}) {
    for (int k = 0; k + 1 < size; ++k) {
      entries.emplace_back(n + k, n + k + 1, Complex(-100, 3));
      entries.emplace_back(n + k + 1, n + k, Complex(-100, -3));
    }
    for (int k = 0; k < size; ++k)
      entries.emplace_back(n + k, n + k, 201.0 + k);
    n += size;
  }
  Eigen::SparseMatrix<Complex> blocks(n, n);
  blocks.setFromTriplets(entries.begin(), entries.end());
  blocks.makeCompressed();
  Eigen::ConjugateGradient<Eigen::SparseMatrix<Complex>, Eigen::Lower | Eigen::Upper, ClusterJacobi>
      clustered;
  clustered.setTolerance(1e-12);
  clustered.compute(blocks);
  EXPECT_EQ(clustered.preconditioner().cluster_count(), 6);
  const Eigen::VectorXcd right = Eigen::VectorXcd::LinSpaced(n, Complex(1, 2), Complex(-3, 1));
  const Eigen::VectorXcd solved = clustered.solve(right);
  EXPECT_LE(clustered.iterations(), 1);
  EXPECT_LT((blocks * solved - right).norm(), 1e-10 * right.norm());
  std::vector<Eigen::Triplet<Complex>> links;
  for (int k = 0; k < 20; ++k) {
    links.emplace_back(k, k, 300.0);
    if (k + 1 < 20) {
      links.emplace_back(k, k + 1, -100.0);
      links.emplace_back(k + 1, k, -100.0);
    }
  }
  Eigen::SparseMatrix<Complex> long_chain(20, 20);
  long_chain.setFromTriplets(links.begin(), links.end());
  long_chain.makeCompressed();
  ClusterJacobi chained;
  chained.compute(long_chain);
  EXPECT_EQ(chained.cluster_count(), 2); // 16 and 4, joined along the chain
}

// Each cluster's block applied as its exact inverse: a complex Hermitian positive definite block of
// four (with a stiff coupling that joins it) gives z = B^-1 r to rounding, also from the lower
// triangle alone; a block that is not positive definite (a matrix no chart makes, as rounding
// might) falls back to Jacobi's 1 / a_ii on its unknowns.
TEST(ClusterJacobi, BlocksAppliedAsTheirInverseOrJacobisWhereNotPositive) {
  Eigen::MatrixXcd block(4, 4);
  block << Complex(9, 0), Complex(-4, 1), Complex(0.5, -2), Complex(1, 0.25), //
      Complex(-4, -1), Complex(8, 0), Complex(-3, 0.5), Complex(0, -1),       //
      Complex(0.5, 2), Complex(-3, -0.5), Complex(7, 0), Complex(-2.5, 1.5),  //
      Complex(1, -0.25), Complex(0, 1), Complex(-2.5, -1.5), Complex(6, 0);
  ASSERT_EQ(Eigen::LLT<Eigen::MatrixXcd>(block).info(), Eigen::Success);
  const Eigen::SparseMatrix<Complex> both = block.sparseView();
  const Eigen::SparseMatrix<Complex> lower = both.triangularView<Eigen::Lower>();
  const Eigen::VectorXcd r = Eigen::VectorXcd::LinSpaced(4, Complex(1, -1), Complex(-2, 3));
  const Eigen::VectorXcd expected = block.llt().solve(r);
  for (const Eigen::SparseMatrix<Complex> *a : {&both, &lower}) {
    ClusterJacobi clusters;
    clusters.compute(*a);
    EXPECT_EQ(clusters.cluster_count(), 1);
    EXPECT_LT((clusters.solve(r) - expected).norm(), 1e-13 * expected.norm());
  }
  Eigen::MatrixXcd indefinite(2, 2); // eigenvalues 3 and -1
  indefinite << Complex(1, 0), Complex(2, 0), Complex(2, 0), Complex(1, 0);
  ClusterJacobi fallback;
  fallback.compute(Eigen::SparseMatrix<Complex>(indefinite.sparseView()));
  EXPECT_EQ(fallback.cluster_count(), 1);
  const Eigen::VectorXcd pair(Eigen::VectorXcd::LinSpaced(2, Complex(2, 1), Complex(-1, 4)));
  EXPECT_LT((fallback.solve(pair) - pair).norm(), 1e-15); // r / a_ii, a_ii = 1
}

// The elimination order of one factorization handed to the next on a subset (as the genus-0
// south-pole step does), and several right-hand sides at once: the same solutions, for both
// factorizations; the order returned lists every free vertex once.
TEST(LaplacianSolver, HandedOnOrderAndSeveralColumnsSolveTheSame) {
  const IcosphereLaplacian sphere;
  const Mesh &mesh = sphere.mesh;
  const int n = sphere.n;
  const Eigen::SparseMatrix<double> &laplacian = sphere.laplacian;
  for (SolverKind kind : {SolverKind::cholmod, SolverKind::eigen_ldlt}) {
    const std::vector<int> first_pinned = {1, 2, 3};
    const std::vector<int> order =
        factor_laplacian(laplacian, kind, first_pinned)->elimination_order();
    std::vector<int> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(int(sorted.size()), n - 3) << solver_name(kind);
    EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
    for (int v : first_pinned)
      EXPECT_FALSE(std::binary_search(sorted.begin(), sorted.end(), v));
    // A Dirichlet problem on a region: the vertices nearest the north pole pinned.
    std::vector<int> pinned;
    for (int v = 0; v < n; ++v)
      if (mesh.vert[size_t(v)].cP()[2] > 0.6) pinned.push_back(v);
    std::vector<int> handed_on = first_pinned;
    handed_on.insert(handed_on.end(), order.begin(), order.end());
    Eigen::MatrixXd right(n, 2);
    for (int v = 0; v < n; ++v) {
      const auto &p = mesh.vert[size_t(v)].cP();
      right(v, 0) = std::cos(2.0 * p[0]);
      right(v, 1) = p[1] * p[2];
    }
    for (int v : pinned)
      right.row(v).setZero();
    const Eigen::MatrixXd own = factor_laplacian(laplacian, kind, pinned)->solve_columns(right);
    const auto reordered = factor_laplacian(laplacian, kind, pinned, handed_on);
    const Eigen::MatrixXd both = reordered->solve_columns(right);
    EXPECT_LT((both - own).cwiseAbs().maxCoeff(), 1e-10 * own.cwiseAbs().maxCoeff());
    for (int k = 0; k < 2; ++k)
      EXPECT_LT((reordered->solve(right.col(k)) - own.col(k)).cwiseAbs().maxCoeff(),
                1e-10 * own.cwiseAbs().maxCoeff());
    // The residual at the free vertices is zero; the pinned ones stay 0.
    const Eigen::MatrixXd residual = laplacian * both - right;
    for (int v = 0; v < n; ++v) {
      if (std::binary_search(pinned.begin(), pinned.end(), v))
        EXPECT_EQ(both.row(v).cwiseAbs().maxCoeff(), 0.0);
      else
        EXPECT_LT(residual.row(v).cwiseAbs().maxCoeff(), 1e-9) << v;
    }
  }
  EXPECT_THROW(factor_laplacian(laplacian, SolverKind::cholmod, {0}, {1, 2, 3}), std::logic_error);
}

// The nested dissection order (METIS) lists every unknown once, is the same on every call (two
// METIS calls at once raced on its random state), and, on a sphere of 41k vertices, leaves
// CHOLMOD's factor fewer entries and less arithmetic than AMD does (why large meshes use it).
TEST(LaplacianSolver, NestedDissectionOrderFillsLessThanMinimumDegree) {
  Mesh mesh;
  make_icosphere(mesh, 6);
  const PreparedMesh prepared = prepare_mesh(mesh);
  const int n = int(mesh.vert.size());
  ASSERT_GT(n, 40000);
  Eigen::SparseMatrix<double> lower =
      cotan_laplacian(n, prepared.edges, prepared.weights).triangularView<Eigen::Lower>();
  lower.makeCompressed();
  const std::vector<int> order =
      nested_dissection_order(n, lower.outerIndexPtr(), lower.innerIndexPtr());
  ASSERT_EQ(int(order.size()), n);
  EXPECT_EQ(nested_dissection_order(n, lower.outerIndexPtr(), lower.innerIndexPtr()), order);
  std::vector<char> seen(size_t(n), 0);
  for (int v : order) {
    ASSERT_TRUE(v >= 0 && v < n);
    EXPECT_FALSE(seen[size_t(v)]) << v;
    seen[size_t(v)] = 1;
  }
  lower.coeffRef(0, 0) += 1.0; // positive definite: one vertex held
  cholmod_sparse matrix{};
  matrix.nrow = matrix.ncol = size_t(n);
  matrix.nzmax = size_t(lower.nonZeros());
  matrix.p = lower.outerIndexPtr();
  matrix.i = lower.innerIndexPtr();
  matrix.x = lower.valuePtr();
  matrix.stype = -1;
  matrix.itype = CHOLMOD_INT;
  matrix.xtype = CHOLMOD_REAL;
  matrix.dtype = CHOLMOD_DOUBLE;
  matrix.sorted = matrix.packed = 1;
  double entries[2], arithmetic[2];
  for (int k = 0; k < 2; ++k) {
    cholmod_common common;
    cholmod_start(&common);
    common.nmethods = 1;
    common.method[0].ordering = k == 0 ? CHOLMOD_AMD : CHOLMOD_GIVEN;
    cholmod_factor *factor = cholmod_analyze_p(
        &matrix, k == 0 ? nullptr : const_cast<int *>(order.data()), nullptr, 0, &common);
    ASSERT_NE(factor, nullptr);
    ASSERT_TRUE(cholmod_factorize(&matrix, factor, &common));
    EXPECT_EQ(factor->minor, size_t(n));
    entries[k] = common.lnz;
    arithmetic[k] = common.fl;
    cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  EXPECT_LT(entries[1], 0.9 * entries[0]);
  EXPECT_LT(arithmetic[1], 0.7 * arithmetic[0]);
}

// The solve that releases its right-hand sides as it reads them (CHOLMOD's supernodal solves in
// place on the permuted columns) gives what the ordinary solve gives, for both factorizations:
// zero residual at the free vertices, exactly 0 at the pinned ones; the right-hand sides are gone.
TEST(LaplacianSolver, ReleasingSolveSolvesTheSame) {
  const IcosphereLaplacian sphere;
  const int n = sphere.n;
  std::vector<int> pinned;
  for (int v = 0; v < n; ++v)
    if (sphere.mesh.vert[size_t(v)].cP()[0] < -0.7) pinned.push_back(v);
  Eigen::MatrixXd right(n, 5);
  for (int v = 0; v < n; ++v) {
    const auto &p = sphere.mesh.vert[size_t(v)].cP();
    for (int k = 0; k < 5; ++k)
      right(v, k) = std::sin((k + 1.0) * p[0] + p[1]) * (v % 7 == 0 ? -3.0 : 1.0);
  }
  for (int v : pinned)
    right.row(v).setZero();
  for (SolverKind kind : {SolverKind::cholmod, SolverKind::eigen_ldlt}) {
    const auto factor = factor_laplacian(sphere.laplacian, kind, pinned);
    const Eigen::MatrixXd usual = factor->solve_columns(right);
    Eigen::MatrixXd given = right;
    const Eigen::MatrixXd released = factor->solve_columns_releasing(std::move(given));
    EXPECT_EQ(given.size(), 0) << solver_name(kind);
    ASSERT_EQ(released.rows(), n);
    ASSERT_EQ(released.cols(), 5);
    EXPECT_LT((released - usual).cwiseAbs().maxCoeff(), 1e-12 * usual.cwiseAbs().maxCoeff())
        << solver_name(kind);
    const Eigen::MatrixXd residual = sphere.laplacian * released - right;
    for (int v = 0; v < n; ++v) {
      if (std::binary_search(pinned.begin(), pinned.end(), v))
        EXPECT_EQ(released.row(v).cwiseAbs().maxCoeff(), 0.0);
      else
        EXPECT_LT(residual.row(v).cwiseAbs().maxCoeff(), 1e-9) << v;
    }
  }
}

// The south-pole step's solve without a factorization of its own: a factor with three vertices
// pinned that eliminated a cap (z > 0.6) last solves the problem with the cap pinned and those
// three free, through its leading block bordered by the three, as a factorization of that problem
// does.
// A few weights changed (raised, as genus 0 does around folds, and one lowered below zero): the
// old factor updated by Woodbury solves as a factorization of the new Laplacian does, and says
// it cannot where the change touches more vertices than allowed.
TEST(LaplacianSolver, ReweightedSolvesAsANewFactorization) {
  const IcosphereLaplacian sphere;
  const Mesh &mesh = sphere.mesh;
  const int n = sphere.n;
  const PreparedMesh &prepared = *sphere.prepared;
  const std::vector<int> pinned = {0, 5, 7};
  const std::vector<double> &before = prepared.weights;
  std::vector<double> after = before;
  for (int e : {3, 10, 11, 40, 41, 42})
    after[size_t(e)] += 0.5;
  after[20] = -0.1;
  for (int e = 0; e < prepared.edges.edge_count(); ++e) // an edge at a pinned vertex changes too
    if (prepared.edges.vertices[size_t(e)][0] == 5 || prepared.edges.vertices[size_t(e)][1] == 5) {
      after[size_t(e)] *= 2;
      break;
    }
  const auto factor =
      factor_laplacian(cotan_laplacian(n, prepared.edges, before), SolverKind::cholmod, pinned);
  const ReweightedSolve updated(*factor, n, pinned, prepared.edges, before, after);
  ASSERT_TRUE(updated.usable());
  Eigen::MatrixXd right(n, 2);
  for (int v = 0; v < n; ++v) {
    const auto &p = mesh.vert[size_t(v)].cP();
    right(v, 0) = std::cos(p[0] + 2 * p[1]);
    right(v, 1) = p[2] * p[2] - p[0];
  }
  for (int v : pinned)
    right.row(v).setZero();
  const Eigen::MatrixXd own =
      factor_laplacian(cotan_laplacian(n, prepared.edges, after), SolverKind::cholmod, pinned)
          ->solve_columns(right);
  const Eigen::MatrixXd both = updated.solve_columns(right);
  EXPECT_LT((both - own).cwiseAbs().maxCoeff(), 1e-9 * own.cwiseAbs().maxCoeff());
  for (int v : pinned)
    EXPECT_EQ(both.row(v).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_FALSE(ReweightedSolve(*factor, n, pinned, prepared.edges, before, after, 4).usable());
}

TEST(LaplacianSolver, LeadingBlockBorderedSolvesAsItsOwnFactorization) {
  const IcosphereLaplacian sphere;
  const Mesh &mesh = sphere.mesh;
  const int n = sphere.n;
  const Eigen::SparseMatrix<double> &laplacian = sphere.laplacian;
  const std::vector<int> corners = {1, 2, 3};
  std::vector<char> in_cap(size_t(n), 0);
  std::vector<int> cap;
  for (int v = 0; v < n; ++v)
    if (mesh.vert[size_t(v)].cP()[2] > 0.6) {
      in_cap[size_t(v)] = 1;
      cap.push_back(v);
    }
  for (int c : corners)
    ASSERT_FALSE(in_cap[size_t(c)]);
  const std::vector<int> order = elimination_order_with_last(laplacian, corners, in_cap);
  ASSERT_EQ(int(order.size()), n - 3);
  for (size_t k = order.size() - cap.size(); k < order.size(); ++k)
    EXPECT_TRUE(in_cap[size_t(order[k])]) << "position " << k;
  const auto factor = factor_laplacian(laplacian, SolverKind::cholmod, corners, order);
  const std::vector<int> kept = factor->elimination_order();
  for (size_t k = kept.size() - cap.size(); k < kept.size(); ++k)
    EXPECT_TRUE(in_cap[size_t(kept[k])]) << "the factorization moved the cap, position " << k;
  Eigen::MatrixXd right(n, 2);
  for (int v = 0; v < n; ++v) {
    const auto &p = mesh.vert[size_t(v)].cP();
    right(v, 0) = std::sin(3.0 * p[0]) + p[2];
    right(v, 1) = p[0] * p[1];
  }
  for (int v : cap)
    right.row(v).setZero();
  const Eigen::MatrixXd own =
      factor_laplacian(laplacian, SolverKind::cholmod, cap)->solve_columns(right);
  const LeadingBlockSolve bordered(*factor, laplacian, int(cap.size()), corners);
  const Eigen::MatrixXd both = bordered.solve_columns(right);
  EXPECT_LT((both - own).cwiseAbs().maxCoeff(), 1e-9 * own.cwiseAbs().maxCoeff());
  for (int v : cap)
    EXPECT_EQ(both.row(v).cwiseAbs().maxCoeff(), 0.0);
  // Later solves reuse the bordering the first one computed.
  const Eigen::MatrixXd again = bordered.solve_columns(right.col(1));
  EXPECT_LT((again - own.col(1)).cwiseAbs().maxCoeff(), 1e-9 * own.cwiseAbs().maxCoeff());
  // Eigen's LDL^T has no leading-block solves: it says so.
  EXPECT_THROW(factor_laplacian(laplacian, SolverKind::eigen_ldlt, corners)
                   ->solve_columns_without_last(right, 1),
               std::logic_error);
}

} // namespace
} // namespace meromorph
