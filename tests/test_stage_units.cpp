// Direct tests of the older stages, each called on its own with inputs whose answer is known
// exactly (the end-to-end tests are elsewhere): taking non-manifold spots apart, splitting into
// parts, taking out zero-area faces, the Laplacian solver, harmonic and conjugate forms, local
// coefficients, periods, the one-ring order, Floater's embedding, fold untangling, generic form
// pairs, the ratio map and the pair search, genus 1's flat corners and areas, parts and the
// texture grid, map quality, sheets and texture coordinates; the clusters' preconditioner.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <set>
#include <sstream>

#include <cholmod.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>

#include "forms/harmonic_forms.h"
#include "forms/holomorphic_forms.h"
#include "forms/holomorphic_pipeline.h"
#include "forms/homology_basis.h"
#include "forms/periods.h"
#include "job/parts_map.h"
#include "maps/branch_star.h"
#include "maps/floater_embedding.h"
#include "maps/fold_untangling.h"
#include "maps/form_pair_search.h"
#include "maps/form_pairs.h"
#include "maps/form_ratio_map.h"
#include "maps/genus0_correction.h"
#include "maps/genus0_map.h"
#include "maps/genus1_branch_placement.h"
#include "maps/south_cap_prediction.h"
#include "maps/star_kernel.h"
#include "mesh/cotan_laplacian.h"
#include "mesh/face_vectors.h"
#include "mesh/mesh_edges.h"
#include "mesh/mesh_from_arrays.h"
#include "mesh/nonmanifold_split.h"
#include "mesh/prepared_mesh.h"
#include "mesh/surface_parts.h"
#include "mesh/topology.h"
#include "mesh/validation.h"
#include "mesh/zero_area_faces.h"
#include "shapes/generated_surfaces.h"
#include "solvers/cluster_jacobi.h"
#include "solvers/hermitian_cg.h"
#include "solvers/laplacian_solver.h"
#include "solvers/leading_block_solve.h"
#include "solvers/metis_order.h"
#include "solvers/reweighted_solve.h"
#include "sphere/arc_grid.h"
#include "sphere/branch_points.h"
#include "sphere/map_quality.h"
#include "sphere/plane_triangles.h"
#include "sphere/sheets.h"
#include "sphere/sphere_geometry.h"
#include "sphere/texture_coordinates.h"
#include "test_support.h"

namespace meromorph {
namespace {

MeshArrays icosphere_arrays(int subdivisions) {
  Mesh mesh;
  make_icosphere(mesh, subdivisions);
  return arrays_from_mesh(mesh);
}

// Two icospheres side by side along x, the second's leftmost vertex merged into the first's
// rightmost: one vertex where two closed surfaces touch.
MeshArrays spheres_touching_at_a_vertex(int &shared) {
  MeshArrays one = icosphere_arrays(1), other = one;
  auto extreme = [](const MeshArrays &arrays, double sign) {
    size_t best = 0;
    for (size_t v = 0; v < arrays.positions.size(); ++v)
      if (sign * arrays.positions[v][0] > sign * arrays.positions[best][0]) best = v;
    return int(best);
  };
  shared = extreme(one, 1);
  const int left = extreme(other, -1);
  const Point3 shift = one.positions[size_t(shared)] - other.positions[size_t(left)];
  std::vector<int> renumber(other.positions.size());
  for (size_t v = 0; v < other.positions.size(); ++v) {
    if (int(v) == left) {
      renumber[v] = shared;
      continue;
    }
    renumber[v] = int(one.positions.size());
    one.positions.push_back(other.positions[v] + shift);
  }
  for (const auto &t : other.triangles)
    one.triangles.push_back(
        {renumber[size_t(t[0])], renumber[size_t(t[1])], renumber[size_t(t[2])]});
  return one;
}

std::vector<Eigen::Vector3d> vertex_positions(const Mesh &mesh) {
  std::vector<Eigen::Vector3d> positions;
  for (const MeshVertex &vertex : mesh.vert)
    positions.push_back(vertex.cP().ToEigenVector<Eigen::Vector3d>());
  return positions;
}

// The vertex positions pushed out onto the unit sphere.
std::vector<Eigen::Vector3d> unit_positions(const Mesh &mesh) {
  std::vector<Eigen::Vector3d> positions = vertex_positions(mesh);
  for (Eigen::Vector3d &p : positions)
    p.normalize();
  return positions;
}

int folded_count(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere) {
  int count = 0;
  for (size_t f = 0; f < in.corners.size(); ++f)
    count += folded_face(in, sphere, int(f));
  return count;
}

TEST(NonmanifoldSplit, TwoSpheresTouchingAtAVertexComeApart) {
  int shared = -1;
  const MeshArrays arrays = spheres_touching_at_a_vertex(shared);
  Mesh touching, split;
  mesh_from_arrays(arrays, touching);
  EXPECT_EQ(compute_topology(touching).euler, 3); // two spheres less a vertex
  const NonmanifoldSplit result = split_nonmanifold(touching, split);
  EXPECT_EQ(result.added_vertices, 1);
  EXPECT_EQ(result.split_vertices, std::vector<int>{shared});
  EXPECT_TRUE(result.split_edges.empty());
  ASSERT_EQ(result.source_vertex.size(), touching.vert.size() + 1);
  EXPECT_EQ(result.source_vertex.back(), shared);
  const Topology topology = compute_topology(split);
  EXPECT_EQ(topology.euler, 4);
  EXPECT_EQ(topology.component_faces.size(), 2u);
  EXPECT_TRUE(topology.boundary_loops.empty());
  EXPECT_EQ(topology.non_manifold_edges, 0);
  ASSERT_EQ(split.face.size(), touching.face.size());
  // The faces keep their order, and each corner's position.
  for (size_t f = 0; f < split.face.size(); ++f)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(split.face[f].cP(k), touching.face[f].cP(k)) << "face " << f;
}

TEST(NonmanifoldSplit, TwoCubesSharingAnEdgeBecomeTwoClosedCubes) {
  const std::string path = ::testing::TempDir() + "cubes_sharing_an_edge.off";
  { std::ofstream(path) << test::cubes_sharing_an_edge_off(); }
  Mesh cubes, split;
  test::load(path, cubes);
  EXPECT_GT(compute_topology(cubes).non_manifold_edges, 0);
  const NonmanifoldSplit result = split_nonmanifold(cubes, split);
  ASSERT_EQ(result.split_edges.size(), 1u);
  EXPECT_EQ(result.added_vertices, 2); // both ends of the edge
  const Topology topology = compute_topology(split);
  EXPECT_EQ(topology.non_manifold_edges, 0);
  EXPECT_TRUE(topology.boundary_loops.empty());
  EXPECT_EQ(topology.component_faces, (std::vector<int>{12, 12}));
  EXPECT_EQ(topology.euler, 4);
}

TEST(SurfaceParts, TwoSpheresAreTwoPartsAndAHoleIsClosed) {
  MeshArrays arrays = icosphere_arrays(1);
  const size_t first_vertices = arrays.positions.size(), first_faces = arrays.triangles.size();
  const MeshArrays second = icosphere_arrays(2);
  for (const Point3 &p : second.positions)
    arrays.positions.push_back(p + Point3(3, 0, 0));
  for (const auto &t : second.triangles)
    arrays.triangles.push_back(
        {t[0] + int(first_vertices), t[1] + int(first_vertices), t[2] + int(first_vertices)});
  arrays.triangles.erase(arrays.triangles.begin() + long(first_faces)); // a hole in the second
  Mesh two;
  mesh_from_arrays(arrays, two);
  const SurfaceParts parts = split_into_closed_parts(two, true);
  ASSERT_EQ(parts.parts.size(), 2u);
  EXPECT_EQ(parts.parts[0].mesh.face.size(), first_faces);
  ASSERT_EQ(parts.holes.size(), 1u);
  EXPECT_EQ(parts.holes[0].part, 1);
  EXPECT_EQ(parts.holes[0].edges, 3);
  for (const SurfacePart &part : parts.parts) {
    const Topology topology = compute_topology(part.mesh);
    EXPECT_TRUE(topology.closed_manifold());
    EXPECT_EQ(topology.genus, std::optional<int>(0));
  }
  // Every input vertex and face is in its part, and comes back from there.
  for (size_t v = 0; v < two.vert.size(); ++v) {
    const SurfacePart &part = parts.parts[size_t(parts.part_of_vertex[v])];
    EXPECT_EQ(part.source_vertex[size_t(parts.vertex_in_part[v])], int(v));
  }
  for (size_t f = 0; f < two.face.size(); ++f) {
    const SurfacePart &part = parts.parts[size_t(parts.part_of_face[f])];
    EXPECT_EQ(part.source_face[size_t(parts.face_in_part[f])], int(f));
  }
}

// An edge (a, b) of an icosphere split at a point: a new vertex m on the edge, its two faces
// split in four.
MeshArrays with_edge_split(double where) {
  MeshArrays arrays = icosphere_arrays(2);
  const std::array<int, 3> first = arrays.triangles[0];
  const int a = first[0], b = first[1], c = first[2];
  size_t across = 0;
  int d = -1;
  for (size_t f = 1; f < arrays.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k)
      if (arrays.triangles[f][size_t(k)] == b && arrays.triangles[f][size_t((k + 1) % 3)] == a) {
        across = f;
        d = arrays.triangles[f][size_t((k + 2) % 3)];
      }
  const int m = int(arrays.positions.size());
  arrays.positions.push_back(arrays.positions[size_t(a)] * (1 - where) +
                             arrays.positions[size_t(b)] * where);
  arrays.triangles[0] = {a, m, c};
  arrays.triangles[across] = {m, a, d};
  arrays.triangles.push_back({m, b, c});
  arrays.triangles.push_back({b, m, d});
  return arrays;
}

int zero_area_count(const Mesh &mesh) {
  int count = 0;
  for (const MeshFace &face : mesh.face)
    count += has_zero_area(face);
  return count;
}

TEST(ZeroAreaFaces, ANeedleIsCollapsedAndTheSurfaceKept) {
  Mesh needled, work;
  mesh_from_arrays(with_edge_split(0.0), needled); // m on a: two needles
  ASSERT_EQ(zero_area_count(needled), 2);
  const ZeroAreaFix fix = take_out_zero_area_faces(needled, work);
  EXPECT_EQ(fix.zero_area_faces.size(), 2u);
  EXPECT_EQ(fix.collapsed_edges, 1);
  EXPECT_EQ(zero_area_count(work), 0);
  EXPECT_EQ(work.face.size(), needled.face.size() - 2);
  EXPECT_EQ(compute_topology(work).genus, std::optional<int>(0));
  ASSERT_EQ(fix.vertex_in_work.size(), needled.vert.size());
  ASSERT_EQ(fix.face_in_work.size(), needled.face.size());
  for (size_t v = 0; v < needled.vert.size(); ++v) {
    if (fix.vertex_in_work[v] >= 0) {
      EXPECT_EQ(work.vert[size_t(fix.vertex_in_work[v])].cP(), needled.vert[v].cP());
    }
  }
}

TEST(ZeroAreaFaces, ACapIsFlippedAway) {
  // The face (a, m, c) with m at the middle of a long side: move c onto the side (a, b) of its
  // other face, which makes that face a cap.
  MeshArrays arrays = icosphere_arrays(2);
  const std::array<int, 3> face = arrays.triangles[0];
  arrays.positions[size_t(face[2])] =
      (arrays.positions[size_t(face[0])] + arrays.positions[size_t(face[1])]) * 0.5;
  Mesh capped, work;
  mesh_from_arrays(arrays, capped);
  ASSERT_GE(zero_area_count(capped), 1);
  const ZeroAreaFix fix = take_out_zero_area_faces(capped, work);
  EXPECT_GE(fix.flipped_edges + fix.collapsed_edges, 1);
  EXPECT_EQ(zero_area_count(work), 0);
  EXPECT_EQ(compute_topology(work).genus, std::optional<int>(0));
  EXPECT_EQ(fix.face_in_work[0], -1); // the cap itself changed
}

// The Laplacian as the sum over edges of w (e_i - e_j)(e_i - e_j)^T, compared entry by entry with
// a dense sum, also where an intrinsic triangulation joins two vertices twice or a vertex to
// itself.
TEST(CotanLaplacian, SumOverEdgesWithRepeatedEdgesAndLoops) {
  MeshEdges edges;
  edges.vertices = {{0, 1}, {1, 2}, {2, 0}, {3, 1}, {1, 3}, {2, 2}, {3, 0}, {0, 1}};
  const std::vector<double> weights = {0.5, -0.25, 2.0, 1.0, 0.75, 3.0, 1.5, 0.125};
  const Eigen::SparseMatrix<double> laplacian = cotan_laplacian(4, edges, weights);
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(4, 4);
  for (size_t e = 0; e < weights.size(); ++e) {
    Eigen::Vector4d d = Eigen::Vector4d::Zero();
    d[edges.vertices[e][0]] += 1;
    d[edges.vertices[e][1]] -= 1;
    expected += weights[e] * d * d.transpose();
  }
  EXPECT_LT((Eigen::MatrixXd(laplacian) - expected).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_TRUE(laplacian.isCompressed());
  EXPECT_EQ(laplacian.nonZeros(), 4 + 2 * 5); // the diagonal and five distinct pairs
  for (int column = 0; column < 4; ++column)  // rows increasing, each once
    for (int k = laplacian.outerIndexPtr()[column] + 1; k < laplacian.outerIndexPtr()[column + 1];
         ++k)
      EXPECT_LT(laplacian.innerIndexPtr()[k - 1], laplacian.innerIndexPtr()[k]);
}

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

TEST(BranchStar, TheOneRingInOrder) {
  Mesh mesh;
  make_icosphere(mesh, 2);
  const FaceIncidence in = face_incidence(mesh);
  std::set<std::array<int, 3>> faces;
  for (const auto &c : in.corners)
    for (int k = 0; k < 3; ++k)
      faces.insert({c[size_t(k)], c[size_t((k + 1) % 3)], c[size_t((k + 2) % 3)]});
  for (int v : {0, 11, 40}) {
    const std::vector<int> ring = ordered_ring(in, v);
    ASSERT_EQ(ring.size(), in.faces_of_vertex[size_t(v)].size()) << v;
    for (size_t j = 0; j < ring.size(); ++j)
      EXPECT_TRUE(faces.count({v, ring[j], ring[(j + 1) % ring.size()]})) << v << " " << j;
  }
}

// The vertices within `rings` rings of vertex v.
std::set<int> within_rings(const FaceIncidence &in, int v, int rings) {
  std::set<int> region = {v};
  for (int ring = 0; ring < rings; ++ring) {
    std::set<int> grown = region;
    for (int u : region)
      for (int f : in.faces_of_vertex[size_t(u)])
        for (int w : in.corners[size_t(f)])
          grown.insert(w);
    region = grown;
  }
  return region;
}

// Chart positions for a Floater embedding: every vertex of `free_set` at the chart's centre, every
// vertex next to it (its rim, fixed) where `chart` puts its point on the unit sphere; false where
// the chart cannot take one.
bool free_at_centre_rim_in_chart(const Mesh &mesh, const FaceIncidence &in,
                                 const std::set<int> &free_set, const GnomonicChart &chart,
                                 PlanePositions &positions) {
  for (int v : free_set)
    for (int f : in.faces_of_vertex[size_t(v)])
      for (int w : in.corners[size_t(f)])
        if (!free_set.count(w) &&
            !chart.to_chart(mesh.vert[size_t(w)].cP().ToEigenVector<Eigen::Vector3d>().normalized(),
                            positions[w]))
          return false;
  for (int v : free_set)
    positions[v] = Eigen::Vector2d::Zero();
  return true;
}

// The faces with a corner in `free_set` whose chart positions turn clockwise or not at all.
int turned_over(const FaceIncidence &in, const std::set<int> &free_set,
                const PlanePositions &positions) {
  int count = 0;
  for (const auto &c : in.corners) {
    if (!free_set.count(c[0]) && !free_set.count(c[1]) && !free_set.count(c[2])) continue;
    const Eigen::Vector2d a = positions.at(c[0]), b = positions.at(c[1]), d = positions.at(c[2]);
    count += !((b - a).x() * (d - a).y() - (b - a).y() * (d - a).x() > 0);
  }
  return count;
}

TEST(FloaterEmbedding, ADiskInTheGnomonicChartHasNoFold) {
  Mesh mesh;
  make_icosphere(mesh, 3);
  const FaceIncidence in = face_incidence(mesh);
  const Eigen::Vector3d centre = mesh.vert[0].cP().ToEigenVector<Eigen::Vector3d>().normalized();
  const GnomonicChart chart(centre);
  Eigen::Vector2d x;
  ASSERT_TRUE(chart.to_chart(centre, x));
  EXPECT_LT(x.norm(), 1e-12);
  const Eigen::Vector3d p = Eigen::Vector3d(0.3, 0.2, 1.0).normalized();
  const GnomonicChart at_p(p);
  Eigen::Vector3d q = Eigen::Vector3d(0.5, -0.1, 0.9).normalized();
  ASSERT_TRUE(at_p.to_chart(q, x));
  EXPECT_LT((at_p.to_sphere(x) - q).norm(), 1e-12);
  // Two rings around vertex 0 free, started all at the centre; the third ring fixed.
  const std::set<int> free_set = within_rings(in, 0, 2);
  PlanePositions positions;
  ASSERT_TRUE(free_at_centre_rim_in_chart(mesh, in, free_set, chart, positions));
  ASSERT_TRUE(floater_embedding(mesh, in, {free_set.begin(), free_set.end()}, positions));
  EXPECT_EQ(turned_over(in, free_set, positions), 0);
}

// Each free vertex at the mean of its neighbours weighted by (tan(alpha / 2) + tan(beta / 2)) /
// |ij| (worked out here from the angles), whether the system is small enough to be solved as a
// dense matrix (2 rings free: 19 vertices) or not (5 rings: 91): the largest residual of those
// equations 1e-12 of the rim's size, and no face turned over.
TEST(FloaterEmbedding, EachFreeVertexAtItsNeighboursWeightedMeanDenseOrSparse) {
  Mesh mesh;
  make_icosphere(mesh, 4);
  const FaceIncidence in = face_incidence(mesh);
  const Eigen::Vector3d centre = mesh.vert[0].cP().ToEigenVector<Eigen::Vector3d>().normalized();
  const GnomonicChart chart(centre);
  auto point = [&](int v) { return mesh.vert[size_t(v)].cP().ToEigenVector<Eigen::Vector3d>(); };
  for (const int rings : {2, 5}) {
    const std::set<int> free_set = within_rings(in, 0, rings);
    EXPECT_EQ(free_set.size(), rings == 2 ? 19u : 91u) << rings;
    PlanePositions positions;
    ASSERT_TRUE(free_at_centre_rim_in_chart(mesh, in, free_set, chart, positions));
    ASSERT_TRUE(floater_embedding(mesh, in, {free_set.begin(), free_set.end()}, positions));
    double worst = 0;
    for (int v : free_set) {
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      double total = 0;
      for (int f : in.faces_of_vertex[size_t(v)]) {
        const auto &c = in.corners[size_t(f)];
        const int k = c[0] == v ? 0 : c[1] == v ? 1 : 2;
        const int a = c[size_t((k + 1) % 3)], b = c[size_t((k + 2) % 3)];
        const Eigen::Vector3d u = point(a) - point(v), w = point(b) - point(v);
        const double half = std::tan(std::acos(u.normalized().dot(w.normalized())) / 2);
        for (const auto &[neighbour, side] : {std::pair{a, u}, std::pair{b, w}}) {
          sum += half / side.norm() * positions.at(neighbour);
          total += half / side.norm();
        }
      }
      worst = std::max(worst, (total * positions.at(v) - sum).norm() / total);
    }
    EXPECT_LT(worst, 1e-12) << rings << " rings";
    EXPECT_EQ(turned_over(in, free_set, positions), 0) << rings << " rings";
  }
}

TEST(FloaterEmbedding, AFixedNeighbourWithoutAPositionIsRefused) {
  // Vertex 0 free, its one-ring fixed but one of them left out of the chart: no embedding (its
  // position would be read from nowhere), and the chart is as it was.
  Mesh mesh;
  make_icosphere(mesh, 2);
  const FaceIncidence in = face_incidence(mesh);
  const std::vector<int> ring = ordered_ring(in, 0);
  PlanePositions chart;
  for (size_t j = 1; j < ring.size(); ++j)
    chart[ring[j]] = Eigen::Vector2d(std::cos(2 * M_PI * double(j) / double(ring.size())),
                                     std::sin(2 * M_PI * double(j) / double(ring.size())));
  chart[0] = Eigen::Vector2d(0.5, 0.5);
  const PlanePositions before = chart;
  EXPECT_FALSE(floater_embedding(mesh, in, {0}, chart));
  EXPECT_EQ(chart, before);
  chart[ring[0]] = Eigen::Vector2d(1, 0);
  EXPECT_TRUE(floater_embedding(mesh, in, {0}, chart));
  EXPECT_LT(chart[0].norm(), 0.2); // inside the regular polygon, near its centre
}

// Every point of every arc is found near every point within the longest path of it, and short
// arcs are near only a few of the grid's cells: 40 random arcs of chord up to 0.4 (and one between
// nearly opposite points, near everywhere), paths of chord up to 0.1.
TEST(ArcGrid, AnArcIsNearEveryPathThatCanMeetIt) {
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  auto random_unit = [&] {
    return Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
  };
  std::vector<Eigen::Vector3d> ends;
  std::vector<std::array<int, 2>> arcs;
  for (int a = 0; a < 40; ++a) {
    const Eigen::Vector3d p = random_unit();
    const Eigen::Vector3d q = (p + 0.4 * std::uniform_real_distribution<double>(0, 1)(random) *
                                       random_unit().cross(p).normalized())
                                  .normalized();
    ends.push_back(p);
    ends.push_back(q);
    arcs.push_back({2 * a, 2 * a + 1});
  }
  const Eigen::Vector3d far = random_unit();
  ends.push_back(far);
  ends.push_back((-far + Eigen::Vector3d(1e-9, 0, 0)).normalized());
  arcs.push_back({80, 81});
  const double longest_path = 0.1;
  const ArcGrid grid(ends, arcs, longest_path);
  size_t listed = 0, looked_up = 0;
  for (size_t a = 0; a + 1 < arcs.size(); ++a)
    for (int step = 0; step <= 20; ++step) {
      const double t = step / 20.0;
      const Eigen::Vector3d z =
          ((1 - t) * ends[size_t(arcs[a][0])] + t * ends[size_t(arcs[a][1])]).normalized();
      for (int k = 0; k < 10; ++k) {
        // A point x with |x - z| at most the longest path, one in ten at that distance.
        const Eigen::Vector3d direction = random_unit().cross(z).normalized();
        const double chord = k == 0 ? longest_path : longest_path * (k / 10.0);
        const double angle = 2 * std::asin(chord / 2);
        const Eigen::Vector3d x = std::cos(angle) * z + std::sin(angle) * direction;
        const std::vector<int> &near = grid.near(x);
        EXPECT_TRUE(std::binary_search(near.begin(), near.end(), int(a))) << a << " " << step;
        EXPECT_TRUE(std::binary_search(near.begin(), near.end(), 40)) << a << " " << step;
        listed += near.size();
        ++looked_up;
      }
    }
  // Each short arc's reach is a small part of the sphere: far fewer than all 41 arcs per point.
  EXPECT_LT(double(listed) / double(looked_up), 6.0); // 2.7 with this seed
}

TEST(StarKernel, TheCentreFarthestInsideEverySide) {
  // A regular hexagon of circumradius 1: its centre, at the inradius cos(30 degrees).
  std::vector<Eigen::Vector2d> hexagon;
  for (int j = 0; j < 6; ++j)
    hexagon.emplace_back(std::cos(M_PI * j / 3) + 5, std::sin(M_PI * j / 3) - 2);
  const auto centre = star_kernel_centre(hexagon);
  ASSERT_TRUE(centre);
  EXPECT_LT((centre->first - Eigen::Vector2d(5, -2)).norm(), 1e-12);
  EXPECT_NEAR(centre->second, std::cos(M_PI / 6), 1e-12);
  // A dart (concave at (0.2, 0)): the point is inside every side's line, the faces all turn
  // counter-clockwise by the margin.
  const std::vector<Eigen::Vector2d> ring = {{1, 0}, {-1, 1}, {0.2, 0}, {-1, -1}};
  const auto inside = star_kernel_centre(ring);
  ASSERT_TRUE(inside);
  EXPECT_GT(inside->second, 0);
  for (size_t j = 0; j < ring.size(); ++j) {
    const Eigen::Vector2d a = ring[j] - inside->first,
                          b = ring[(j + 1) % ring.size()] - inside->first;
    const double height = (a.x() * b.y() - a.y() * b.x()) / (b - a).norm();
    EXPECT_GE(height, inside->second - 1e-12) << j;
  }
  // Turning the other way round the point (all faces turned over), or a bow that crosses
  // itself: no kernel.
  EXPECT_FALSE(star_kernel_centre({hexagon.rbegin(), hexagon.rend()}));
  EXPECT_FALSE(star_kernel_centre({{0, 0}, {1, 1}, {1, 0}, {0, 1}}));
  EXPECT_FALSE(star_kernel_centre({{0, 0}, {1, 0}}));
}

TEST(FoldUntangling, AVertexPulledAcrossItsRingComesBack) {
  Mesh mesh;
  make_icosphere(mesh, 3);
  const PreparedMesh prepared = prepare_mesh(mesh);
  std::vector<Eigen::Vector3d> sphere = unit_positions(mesh);
  ASSERT_EQ(folded_count(prepared.incidence, sphere), 0);
  // Vertex 0 pushed over its first neighbour: the faces around it turn over.
  const int neighbour = ordered_ring(prepared.incidence, 0)[0];
  sphere[0] = (sphere[size_t(neighbour)] * 2 - sphere[0]).normalized();
  ASSERT_GT(folded_count(prepared.incidence, sphere), 0);
  EXPECT_GE(untangle_folds(prepared, sphere, {}), 1);
  EXPECT_EQ(folded_count(prepared.incidence, sphere), 0);
  // The fixed vertices stay where they are.
  std::vector<Eigen::Vector3d> again = unit_positions(mesh);
  again[0] = (again[size_t(neighbour)] * 2 - again[0]).normalized();
  const Eigen::Vector3d held = again[0];
  untangle_folds(prepared, again, {0});
  EXPECT_EQ(again[0], held);
}

TEST(FoldUntangling, AFoldInsideABranchVertexsStarIsReembeddedWithItsOneRing) {
  // The double cover w = z^2 of the sphere, branched at vertex 0 (z = 0) and at the vertex
  // opposite it: no face is folded. One vertex of vertex 0's one-ring pushed over its neighbour
  // folds faces of the star itself. Keeping the one-ring, the star's rings cannot unfold them;
  // moving it (the branch vertex pinned), they unfold and vertex 0 still winds twice.
  Mesh mesh;
  make_icosphere(mesh, 3);
  const PreparedMesh prepared = prepare_mesh(mesh);
  const FaceIncidence &in = prepared.incidence;
  const std::vector<Eigen::Vector3d> positions = unit_positions(mesh);
  const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(positions[0], to_sphere(0.0));
  std::vector<Eigen::Vector3d> sphere;
  for (const Eigen::Vector3d &p : positions) {
    const PlaneValue z = to_plane_value(turn * p);
    sphere.push_back(to_sphere(z.infinite ? PlaneValue{0.0, true} : PlaneValue{z.w * z.w, false}));
  }
  ASSERT_EQ(folded_count(in, sphere), 0);
  ASSERT_EQ(vertex_winding(in, sphere, 0), 2);
  const std::vector<int> ring = ordered_ring(in, 0);
  sphere[size_t(ring[0])] = (sphere[size_t(ring[1])] * 2 - sphere[size_t(ring[0])]).normalized();
  const int folded = folded_count(in, sphere);
  ASSERT_GT(folded, 0);
  auto folded_after = [&](OneRing one_ring, int rings) {
    std::vector<Eigen::Vector3d> moved = sphere;
    const auto placed = reembed_around_branch(mesh, in, sphere, 0, rings, one_ring);
    if (placed)
      for (const auto &[v, p] : *placed)
        moved[size_t(v)] = p;
    return std::make_pair(folded_count(in, moved), vertex_winding(in, moved, 0));
  };
  for (int rings = 2; rings <= 4; ++rings) {
    EXPECT_EQ(folded_after(OneRing::kept, rings).first, folded) << rings;
    EXPECT_EQ(folded_after(OneRing::moves, rings), std::make_pair(0, 2)) << rings;
  }
}

TEST(FormPairs, GenericAndTheSameOnEveryCall) {
  for (int genus : {2, 3, 5}) {
    const std::vector<FormPair> pairs = generic_form_pairs(genus);
    ASSERT_GE(pairs.size(), 3u);
    for (const FormPair &pair : pairs) {
      ASSERT_EQ(pair.first.size(), genus);
      ASSERT_EQ(pair.second.size(), genus);
      std::vector<std::complex<double>> ratios;
      for (int k = 0; k < genus; ++k) {
        EXPECT_GT(std::abs(pair.first[k]), 1e-3);
        EXPECT_GT(std::abs(pair.second[k]), 1e-3);
        ratios.push_back(pair.first[k] / pair.second[k]);
      }
      for (int i = 0; i < genus; ++i)
        for (int j = i + 1; j < genus; ++j)
          EXPECT_GT(std::abs(ratios[size_t(i)] - ratios[size_t(j)]), 1e-3) << genus;
    }
    const std::vector<FormPair> again = generic_form_pairs(genus);
    for (size_t i = 0; i < pairs.size(); ++i)
      EXPECT_EQ(pairs[i].first, again[i].first);
  }
}

TEST(FormRatioMap, GenusTwoRatioHasDegreeTwoAndTheSearchKeepsIt) {
  Mesh eight;
  test::load(test::data_path("eight.off"), eight);
  const PreparedMesh prepared = prepare_mesh(eight);
  const HolomorphicForms forms = compute_holomorphic_forms(prepared, SolverKind::cholmod, {});
  ASSERT_EQ(forms.genus, 2);
  const Eigen::VectorXcd sum = forms.normalized[0] + forms.normalized[1];
  const Eigen::VectorXcd difference = forms.normalized[0] - forms.normalized[1];
  const Eigen::MatrixXcd dz =
      dz_coefficients(eight, prepared.edges, prepared.geometry, {sum, difference});
  const std::vector<PlaneValue> values =
      form_ratio_map(prepared, {std::vector<Complex>(dz.row(0).begin(), dz.row(0).end()),
                                std::vector<Complex>(dz.row(1).begin(), dz.row(1).end())});
  ASSERT_EQ(values.size(), eight.vert.size());
  std::vector<Eigen::Vector3d> sphere = to_sphere(values);
  // The signed image area is twice the sphere's before any branch point is placed.
  const std::vector<double> solid = face_solid_angles(eight, sphere);
  EXPECT_NEAR(std::accumulate(solid.begin(), solid.end(), 0.0) / (4 * M_PI), 2.0, 0.05);

  const PairSearch search = search_form_pairs(prepared, forms, {-1, -1}, true, Progress{});
  EXPECT_GE(search.attempts, 1);
  sphere = to_sphere(search.values);
  const Branching branching = analyse_branching(eight, sphere, -2);
  EXPECT_EQ(branching.degree, 2);
  EXPECT_TRUE(branching.riemann_hurwitz_ok);
  EXPECT_EQ(branching.branch_vertices.size(), 6u);
}

// A coarse genus-8 chain with needles: some pairs' maps lose a sheet where their zeros and poles
// crowd (image area 2g - 4 spheres before any snapping), which snapping does not give back. The
// search snaps only a pair whose map has the right area, and that one is generic.
TEST(FormPairSearch, MapsThatLoseASheetAreNotSnappedWhileAnotherPairIsGeneric) {
  Mesh mesh;
  make_genus_surface(mesh, 8, 24);
  inject_needles(mesh, 0.2);
  const HolomorphicForms forms = compute_holomorphic_forms(mesh);
  const PreparedMesh prepared = prepare_mesh(mesh);
  ASSERT_EQ(forms.genus, 8);
  const Eigen::MatrixXcd normalized_dz =
      dz_coefficients(mesh, prepared.edges, prepared.geometry, forms.normalized);
  // Each pair's map before snapping, its sheets counted from the image area.
  int sheet_lost = 0;
  for (const FormPair &pair : generic_form_pairs(forms.genus)) {
    const double sheets = image_area_over_4pi(
        mesh, to_sphere(form_ratio_map(prepared, ratio_dz(pair, normalized_dz))));
    EXPECT_NEAR(sheets, std::round(sheets), 1e-6) << "a closed surface's image: whole spheres";
    if (std::lround(sheets) != 14) ++sheet_lost;
  }
  ASSERT_GE(sheet_lost, 2) << "the surface no longer exercises the case";

  const PairSearch search = search_form_pairs(prepared, forms, {-1, -1}, true, Progress{});
  const Branching branching = analyse_branching(mesh, to_sphere(search.values), 2 - 2 * 8);
  EXPECT_EQ(branching.degree, 14);
  EXPECT_TRUE(branching.riemann_hurwitz_ok);
  EXPECT_GT(search.attempts, 1);
  EXPECT_EQ(search.snapped_pairs, 1) << "only the generic pair's map is snapped";
}

// The pair search judges the later pairs from screening solves (form_ratio_map.h): on a coarse
// genus-5 chain whose pairs all crowd, each pair's screening map has the same image area as its
// full solve and its crowded faces within two; solved again from the screening map, the map is
// the full solve's to the tolerance.
TEST(FormRatioMap, ScreeningSolvesJudgePairsAsFullOnesAndStartTheFullSolve) {
  Mesh mesh;
  make_genus_surface(mesh, 5, 20);
  const HolomorphicForms forms = compute_holomorphic_forms(mesh);
  const PreparedMesh prepared = prepare_mesh(mesh);
  const Eigen::MatrixXcd normalized_dz =
      dz_coefficients(mesh, prepared.edges, prepared.geometry, forms.normalized);
  const std::vector<FormPair> pairs = generic_form_pairs(forms.genus);
  int crowding_pairs = 0;
  for (size_t k = 0; k < 3; ++k) {
    const RatioDz dz = ratio_dz(pairs[k], normalized_dz);
    const std::vector<PlaneValue> full = form_ratio_map(prepared, dz);
    const std::vector<PlaneValue> screened =
        form_ratio_map(prepared, dz, {screening_tolerance, nullptr});
    const std::vector<Eigen::Vector3d> full_sphere = to_sphere(full),
                                       screened_sphere = to_sphere(screened);
    EXPECT_EQ(std::lround(image_area_over_4pi(mesh, screened_sphere)),
              std::lround(image_area_over_4pi(mesh, full_sphere)))
        << k;
    const int crowded = crowded_faces(prepared.incidence, full_sphere);
    EXPECT_NEAR(crowded_faces(prepared.incidence, screened_sphere), crowded, 2) << k;
    crowding_pairs += crowded > 0;
    double screened_apart = 0, again_apart = 0;
    const std::vector<Eigen::Vector3d> again =
        to_sphere(form_ratio_map(prepared, dz, {RatioSolve().tolerance, &screened}));
    for (size_t v = 0; v < full.size(); ++v) {
      screened_apart = std::max(screened_apart, (screened_sphere[v] - full_sphere[v]).norm());
      again_apart = std::max(again_apart, (again[v] - full_sphere[v]).norm());
    }
    EXPECT_GT(screened_apart, 1e-6) << k << ": the screening solve stops early";
    EXPECT_LT(again_apart, 1e-4) << k;
    EXPECT_LT(again_apart, 0.1 * screened_apart) << k;
  }
  EXPECT_GE(crowding_pairs, 2) << "the surface no longer crowds";
}

// A ratio map solved in passes (form_ratio_map.h's RatioMap): the screening pass and then the
// full one end at the very values of one full pass (and of form_ratio_map), in the same steps,
// on a raw marching-cubes genus-4 surface with needles (clustered charts).
TEST(FormRatioMap, ScreeningThenFullPassIsTheFullSolve) {
  Mesh mesh;
  make_genus_surface(mesh, 4, 20, false);
  inject_needles(mesh, 0.3);
  const HolomorphicForms forms = compute_holomorphic_forms(mesh);
  const PreparedMesh prepared = prepare_mesh(mesh);
  const Eigen::MatrixXcd normalized_dz =
      dz_coefficients(mesh, prepared.edges, prepared.geometry, forms.normalized);
  const RatioDz dz = ratio_dz(generic_form_pairs(forms.genus)[0], normalized_dz);
  RatioMap in_passes(prepared, dz);
  const std::vector<PlaneValue> screened = in_passes.values(screening_tolerance);
  const int screening_steps = in_passes.steps();
  const std::vector<PlaneValue> full = in_passes.values(RatioSolve().tolerance);
  RatioMap at_once(prepared, dz);
  const std::vector<PlaneValue> direct = at_once.values(RatioSolve().tolerance);
  EXPECT_GT(screening_steps, 0);
  EXPECT_LT(screening_steps, in_passes.steps());
  EXPECT_EQ(in_passes.steps(), at_once.steps());
  const std::vector<PlaneValue> wrapped = form_ratio_map(prepared, dz);
  size_t differing = 0, moved_on = 0;
  for (size_t v = 0; v < full.size(); ++v) {
    differing += full[v].w != direct[v].w || full[v].infinite != direct[v].infinite ||
                 wrapped[v].w != direct[v].w;
    moved_on += screened[v].w != full[v].w;
  }
  EXPECT_EQ(differing, 0u);
  EXPECT_GT(moved_on, full.size() / 2) << "the full pass moved the screening values on";
}

TEST(Genus1Placement, FlatCornersAndAreasOfAGridTorus) {
  Mesh mesh;
  make_grid_torus(mesh, 2.0, 1.0, 48, 24);
  const PreparedMesh prepared = prepare_mesh(mesh);
  const HolomorphicForms forms = compute_holomorphic_forms(prepared, SolverKind::cholmod, {});
  const Eigen::VectorXcd &psi = forms.normalized[0];
  // The grid's quads are conformal rectangles: every widest corner is a right angle.
  for (double corner : widest_flat_corners(prepared, psi))
    EXPECT_NEAR(corner, M_PI / 2, 0.05);
  // The flat area of the stars adds up to three times the flat torus's, Im tau (A-period 1).
  const std::vector<double> ratio = flat_area_ratios(prepared, psi);
  std::vector<double> star(mesh.vert.size(), 0.0);
  for (size_t f = 0; f < mesh.face.size(); ++f)
    for (int v : prepared.incidence.corners[f])
      star[size_t(v)] += prepared.geometry.areas[f];
  double flat = 0;
  for (size_t v = 0; v < star.size(); ++v)
    flat += ratio[v] * star[v];
  EXPECT_NEAR(flat, 3 * std::abs(forms.riemann_matrix(0, 0).imag()), 1e-9);
}

TEST(Genus0Correction, FoldedPlaneFacesByOrientationInTheirChart) {
  FaceIncidence in;
  in.corners = {{0, 1, 2}, {0, 2, 1}, {3, 4, 5}};
  const std::vector<PlaneValue> values = {{{0, 0}},  {{0.5, 0}}, {{0, 0.5}},
                                          {{10, 0}}, {{0, -10}}, {{20, 0}}};
  // The third face, outside the unit circle, is judged in 1 / z: (0.1, 0.1i, 0.05) turns
  // counter-clockwise there. The second is the first turned over.
  EXPECT_EQ(folded_plane_faces(in, values), std::vector<int>{1});
}

// The squared-moduli tests answer as the std::abs ones they replace, near the thresholds, far
// out, far in, at zero and for NaN.
TEST(PlaneTriangles, AnswerAsTheTestsWithStdAbs) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1, 1), exponent(-170, 170);
  auto value = [&] { // scales from 1e-170 to 1e170, some exactly 0 or on the unit circle
    switch (random() % 8) {
    case 0:
      return Complex(0, 0);
    case 1:
      return std::polar(1.0, 3 * unit(random)) * (1 + 1e-16 * unit(random));
    default:
      return Complex(unit(random), unit(random)) * std::pow(10.0, exponent(random));
    }
  };
  size_t checked = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const Complex w = value();
    ASSERT_EQ(inside_unit_circle(w), std::abs(w) < 1) << w;
    const double bound = random() % 4 == 0 ? std::abs(w) : std::abs(value());
    ASSERT_EQ(shorter_than(w, bound), !(std::abs(w) >= bound)) << w << " " << bound;
    Complex z[3] = {value(), value(), value()};
    if (random() % 2) { // a triangle near the resolution: edges of about 1e-12 of its distance
      const double ratio = 1e-12 * (1 + (random() % 3 == 0 ? 1e-15 : 1e-3) * unit(random));
      z[1] = z[0] + std::polar(std::abs(z[0]) * ratio, 3 * unit(random));
      z[2] = z[0] + (z[1] - z[0]) * std::polar(0.5 + 0.5 * unit(random), unit(random));
    }
    const double size = std::max(std::abs(z[1] - z[0]), std::abs(z[2] - z[0]));
    const double distance = std::max({std::abs(z[0]), std::abs(z[1]), std::abs(z[2])});
    const bool unresolved = size < 1e-12 * distance;
    ASSERT_EQ(below_resolution(z), unresolved) << z[0] << z[1] << z[2];
    ASSERT_EQ(folded_in_the_plane(z),
              !unresolved && std::imag(std::conj(z[1] - z[0]) * (z[2] - z[0])) <= 0);
    ++checked;
  }
  EXPECT_EQ(checked, 200000u);
  const double nan = std::nan("");
  EXPECT_FALSE(inside_unit_circle(Complex(nan, 0)));
  EXPECT_TRUE(shorter_than(Complex(nan, 0), 1.0));
  EXPECT_TRUE(shorter_than(Complex(1, 0), nan));
  EXPECT_FALSE(shorter_than(Complex(0, 0), -1.0));
  const Complex point[3] = {Complex(1, 1), Complex(1, 1), Complex(1, 1)};
  EXPECT_TRUE(below_resolution(point));
  EXPECT_FALSE(folded_in_the_plane(point));
}

TEST(Genus0Map, RefinementOnlyWhereTheValuesCrowd) {
  MeshEdges edges;
  edges.vertices = {{0, 1}, {1, 2}, {2, 0}};
  Eigen::VectorXcd z(3);
  z << Complex(0, 0), Complex(1, 0), Complex(0, 1);
  EXPECT_FALSE(values_crowd(edges, z));
  // A long thin part's tip: an edge of 1e-12 of the map's size, where one solve's rounding
  // (relative to the whole map) reaches the edge itself.
  z[1] = Complex(1e-12, 0);
  EXPECT_TRUE(values_crowd(edges, z));
  z[1] = Complex(1e-6, 0);
  EXPECT_FALSE(values_crowd(edges, z));
}

// The south-pole step's cap predicted from a coarse map (south_cap_prediction.h): none on a mesh
// of at most 4096 vertices (the coarse map would be the mesh's own, a factorization as dear as
// the one the prediction saves); above, about a tenth of the vertices, opposite the puncture on a
// sphere (a pinned-pole map is a stereographic projection from the pole there).
TEST(SouthCapPrediction, NoneWhereNothingIsCoarsenedElseACapOppositeThePole) {
  for (int subdivisions : {4, 5}) { // 2562 and 10242 vertices
    Mesh sphere;
    make_icosphere(sphere, subdivisions);
    const PreparedMesh prepared = prepare_mesh(sphere);
    const int pole = default_pole_face(prepared);
    int raised = 0;
    const std::vector<char> cap =
        predicted_south_cap(prepared, positive_weights(prepared.weights, {}, raised), pole);
    const size_t n = sphere.vert.size();
    if (n <= 4096) {
      EXPECT_TRUE(cap.empty()) << n << " vertices";
      continue;
    }
    ASSERT_EQ(cap.size(), n);
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    int count = 0;
    for (size_t v = 0; v < n; ++v)
      if (cap[v]) {
        centroid += sphere.vert[v].cP().ToEigenVector<Eigen::Vector3d>();
        ++count;
      }
    EXPECT_NEAR(double(count) / double(n), south_cap_share, 0.03);
    Eigen::Vector3d pole_centre = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
      pole_centre += sphere.face[size_t(pole)].cP(k).ToEigenVector<Eigen::Vector3d>();
    EXPECT_LT(centroid.normalized().dot(pole_centre.normalized()), -0.9);
  }
}

TEST(PartsMap, TextureGridAndEachPartMappedOnItsOwn) {
  EXPECT_EQ(texture_grid_cells(1), 1);
  EXPECT_EQ(texture_grid_cells(2), 2);
  EXPECT_EQ(texture_grid_cells(4), 2);
  EXPECT_EQ(texture_grid_cells(5), 3);
  MeshArrays arrays = icosphere_arrays(2);
  const size_t first = arrays.positions.size();
  Mesh torus;
  make_grid_torus(torus, 2.0, 1.0, 32, 16);
  const MeshArrays second = arrays_from_mesh(torus);
  for (const Point3 &p : second.positions)
    arrays.positions.push_back(p + Point3(6, 0, 0));
  for (const auto &t : second.triangles)
    arrays.triangles.push_back({t[0] + int(first), t[1] + int(first), t[2] + int(first)});
  Mesh two;
  mesh_from_arrays(arrays, two);
  const Parameterization map =
      parameterize_parts(two, validate_mesh(two), ParameterizeOptions{}, Progress{});
  ASSERT_EQ(map.components.size(), 2u);
  EXPECT_EQ(map.components[0].genus, 0);
  EXPECT_EQ(map.components[1].genus, 1);
  EXPECT_EQ(map.components[0].degree, 1);
  EXPECT_EQ(map.components[1].degree, 2);
  EXPECT_EQ(map.branch_points.size(), 4u); // the torus's
  ASSERT_EQ(map.sphere.size(), two.vert.size());
  for (const Eigen::Vector3d &p : map.sphere)
    EXPECT_NEAR(p.norm(), 1.0, 1e-9);
}

TEST(MapQuality, TheIdentityIsExactAndAMirrorFoldsEverything) {
  Mesh mesh;
  make_icosphere(mesh, 3);
  const std::vector<Eigen::Vector3d> sphere = vertex_positions(mesh);
  const MapQuality identity = measure_map_quality(mesh, sphere, {});
  EXPECT_NEAR(identity.overall.angle_error_mean_degrees, 0.0, 1e-9);
  EXPECT_NEAR(identity.overall.quasi_conformal_max, 1.0, 1e-9);
  EXPECT_EQ(identity.overall.folded_faces, 0);
  EXPECT_NEAR(face_angle_error_degrees(mesh, sphere, 7), 0.0, 1e-9);
  std::vector<Eigen::Vector3d> mirrored = sphere;
  for (Eigen::Vector3d &p : mirrored)
    p.x() = -p.x();
  const MapQuality mirror = measure_map_quality(mesh, mirrored, {});
  EXPECT_EQ(mirror.overall.folded_faces, int(mesh.face.size()));
  EXPECT_EQ(mirror.folded_face_indices.size(), mesh.face.size());
}

TEST(Sheets, TheSquareOfAMoebiusMapHasTwoLayersEachCoveringTheSphere) {
  // z -> (chart at p)^2 on an icosphere: degree 2, branched at p and its antipode -p.
  Mesh mesh;
  make_icosphere(mesh, 4);
  const std::vector<Eigen::Vector3d> positions = vertex_positions(mesh);
  const int p = 0;
  int antipode = -1;
  for (size_t v = 0; v < positions.size(); ++v)
    if ((positions[v] + positions[size_t(p)]).norm() < 1e-9) antipode = int(v);
  ASSERT_GE(antipode, 0);
  std::vector<Eigen::Vector3d> sphere;
  const Eigen::Vector3d north(0, 0, 1);
  for (const Eigen::Vector3d &q : positions) {
    const Complex w = chart_at(positions[size_t(p)].normalized(), q.normalized());
    sphere.push_back(from_chart(north, w * w));
  }
  const std::vector<int> branch = {p, antipode};
  const Sheets sheets = label_sheets(mesh, build_mesh_edges(mesh), sphere, branch, 2);
  ASSERT_EQ(sheets.count, 2);
  ASSERT_EQ(sheets.coverage.size(), 2u);
  for (double coverage : sheets.coverage)
    EXPECT_NEAR(coverage, 1.0, 0.02);
  ASSERT_EQ(sheets.face_layer.size(), mesh.face.size());
  ASSERT_EQ(sheets.vertex_layer.size(), mesh.vert.size());
  const Branching branching = analyse_branching(mesh, sphere, 2);
  EXPECT_EQ(branching.degree, 2);
  EXPECT_EQ(branching.branch_vertices.size(), 2u);
}

TEST(TextureCoordinates, LongitudeLatitudeAndTheSeam) {
  auto uv = [](double x, double y, double z) {
    return texture_coordinate(Eigen::Vector3d(x, y, z), UvKind::spherical);
  };
  EXPECT_NEAR(uv(1, 0, 0)[0], 0.5, 1e-12);
  EXPECT_NEAR(uv(1, 0, 0)[1], 0.5, 1e-12);
  EXPECT_NEAR(uv(0, 1, 0)[0], 0.75, 1e-12);
  EXPECT_NEAR(uv(0, 0, 1)[1], 0.0, 1e-12);
  EXPECT_NEAR(uv(0, 0, -1)[1], 1.0, 1e-12);
  const Eigen::Vector3d w(0.3, -0.4, 0.5);
  const std::array<double, 2> plane = texture_coordinate(w.normalized(), UvKind::stereographic);
  const Complex expected = to_plane(w.normalized());
  EXPECT_NEAR(plane[0], expected.real(), 1e-12);
  EXPECT_NEAR(plane[1], expected.imag(), 1e-12);
  // A face across longitude 180 degrees: its wedges are unwrapped, no corner a whole turn away.
  MeshArrays arrays;
  arrays.positions = {Point3(-1, 0.05, 0), Point3(-1, -0.05, 0), Point3(-1, 0, 0.1)};
  arrays.triangles = {{0, 1, 2}};
  Mesh triangle;
  mesh_from_arrays(arrays, triangle);
  std::vector<Eigen::Vector3d> sphere = unit_positions(triangle);
  const TextureCoordinates texture = texture_coordinates(triangle, sphere, UvKind::spherical);
  EXPECT_GT(std::abs(texture.vertex[0][0] - texture.vertex[1][0]), 0.9); // the seam
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_LT(std::abs(texture.wedge[0][size_t(i)][0] - texture.wedge[0][size_t(j)][0]), 0.1);
}

} // namespace
} // namespace meromorph
