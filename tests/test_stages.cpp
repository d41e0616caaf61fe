// Direct tests of the map's stages, each on its own (the end-to-end tests are elsewhere): the
// prepared mesh, boundary chaining, genus 1's origin candidates and retries, the zero-area
// images, the validity reasons and how param handles each finding.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>

#include <gtest/gtest.h>

#include "forms/holomorphic_pipeline.h"
#include "job/surface_map.h"
#include "job/zero_area_images.h"
#include "maps/genus1_map.h"
#include "maps/map_validity.h"
#include "maps/written_map.h"
#include "mesh/mesh_from_arrays.h"
#include "mesh/prepared_mesh.h"
#include "mesh/unit_scale.h"
#include "mesh/validation.h"
#include "shapes/generated_surfaces.h"
#include "sphere/branch_points.h"
#include "test_support.h"

namespace meromorph {
namespace {

TEST(PreparedMesh, HoldsWhatEveryStageReads) {
  Mesh mesh;
  make_grid_torus(mesh, 2.0, 1.0, 24, 12);
  const PreparedMesh prepared = prepare_mesh(mesh);
  const size_t faces = mesh.face.size(), vertices = mesh.vert.size();
  EXPECT_EQ(size_t(prepared.edges.edge_count()), 3 * faces / 2);
  EXPECT_EQ(prepared.weights.size(), size_t(prepared.edges.edge_count()));
  ASSERT_EQ(prepared.incidence.corners.size(), faces);
  ASSERT_EQ(prepared.edges_at_vertex.size(), vertices);
  // Every edge is at both its ends; every face around each of its corners.
  for (int e = 0; e < prepared.edges.edge_count(); ++e)
    for (int end : prepared.edges.vertices[e]) {
      const auto &at = prepared.edges_at_vertex[size_t(end)];
      EXPECT_NE(std::find(at.begin(), at.end(), e), at.end()) << "edge " << e;
    }
  for (size_t f = 0; f < faces; ++f)
    for (int v : prepared.incidence.corners[f]) {
      const auto &around = prepared.incidence.faces_of_vertex[size_t(v)];
      EXPECT_NE(std::find(around.begin(), around.end(), int(f)), around.end()) << "face " << f;
    }
  // A third of each face to each corner: the vertex areas add up to the surface's, which for
  // this grid torus is close to the smooth torus's 4 pi^2 R r (an inscribed polyhedron: less).
  const double total =
      std::accumulate(prepared.vertex_areas.begin(), prepared.vertex_areas.end(), 0.0);
  EXPECT_NEAR(total,
              std::accumulate(prepared.geometry.areas.begin(), prepared.geometry.areas.end(), 0.0),
              1e-12 * total);
  EXPECT_LT(total, 4 * M_PI * M_PI * 2.0);
  EXPECT_GT(total, 0.97 * 4 * M_PI * M_PI * 2.0);
}

TEST(BoundaryChains, LoopsOfAFaceSetAndWhereHolesTouch) {
  // A square of two triangles: one loop of four, in the faces' walking direction.
  const BoundaryLoops square = chain_boundary({{0, 1, 2}, {0, 2, 3}});
  ASSERT_EQ(square.loops.size(), 1u);
  EXPECT_EQ(square.pinched_vertex, -1);
  std::vector<int> loop = square.loops.front();
  std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  EXPECT_EQ(loop, (std::vector<int>{0, 1, 2, 3}));
  // Two triangles touching at vertex 0: two boundary half-edges start there.
  const BoundaryLoops bowtie = chain_boundary({{0, 1, 2}, {0, 3, 4}});
  EXPECT_TRUE(bowtie.loops.empty());
  EXPECT_EQ(bowtie.pinched_vertex, 0);
  // A strip closed into a ring (an annulus of 8 triangles): two loops, each in walking order.
  std::vector<std::array<int, 3>> annulus;
  for (int k = 0; k < 4; ++k) {
    const int a = k, b = (k + 1) % 4, c = 4 + k, d = 4 + (k + 1) % 4;
    annulus.push_back({a, b, d});
    annulus.push_back({a, d, c});
  }
  const BoundaryLoops two = chain_boundary(annulus);
  ASSERT_EQ(two.loops.size(), 2u);
  EXPECT_EQ(two.loops[0], (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(two.loops[1], (std::vector<int>{4, 7, 6, 5}));
  // A closed surface has none.
  Mesh mesh;
  make_icosphere(mesh, 1);
  EXPECT_TRUE(chain_boundary(face_incidence(mesh).corners).loops.empty());
}

// Ring distances against a search of the test's own (a breadth-first search over the faces'
// corners with a std::map); in the order of the vertices; farther ones absent.
TEST(RingDistances, BreadthFirstRingsInVertexOrder) {
  Mesh mesh;
  make_icosphere(mesh, 2);
  const FaceIncidence in = face_incidence(mesh);
  const std::vector<int> sources = {0, 17, 17};
  std::map<int, int> expected;
  std::vector<int> frontier;
  for (int v : sources)
    if (expected.emplace(v, 0).second) frontier.push_back(v);
  for (int ring = 1; ring <= 3; ++ring) {
    std::vector<int> next;
    for (int v : frontier)
      for (int f : in.faces_of_vertex[size_t(v)])
        for (int w : in.corners[size_t(f)])
          if (expected.emplace(w, ring).second) next.push_back(w);
    frontier = next;
  }
  for (int repeat = 0; repeat < 2; ++repeat) { // (the second search starts from a clean slate)
    const RingDistances rings = ring_distances(in, sources, 3);
    ASSERT_EQ(rings.size(), expected.size());
    auto at = expected.begin();
    for (const auto &[v, d] : rings) {
      EXPECT_EQ(v, at->first);
      EXPECT_EQ(d, at->second);
      EXPECT_EQ(rings.at(v), d);
      ++at;
    }
    int beyond = 0;
    while (expected.count(beyond))
      ++beyond;
    EXPECT_FALSE(rings.count(beyond));
    EXPECT_THROW(rings.at(beyond), std::out_of_range);
  }
}

TEST(Genus1Origins, CandidatesSitOnTheBodyAndRetriesFindAValidMap) {
  // A ball with a hole and four limbs (13 times longer than thick): every origin candidate is on
  // the ball (radius 1), none on a limb, where the flat metric is exponentially small.
  Mesh mesh;
  make_tentacle_blob(mesh, 4, 4.0, 30, true);
  Mesh unit;
  copy_at_unit_scale(mesh, unit_scale_of(mesh), unit);
  const PreparedMesh prepared = prepare_mesh(unit);
  const HolomorphicForms forms = compute_holomorphic_forms(prepared, SolverKind::cholmod, {});
  const std::vector<int> origins = genus1_origin_candidates(
      prepared, forms.normalized[0], WeierstrassP(Complex(1, 0), forms.riemann_matrix(0, 0)));
  ASSERT_FALSE(origins.empty());
  EXPECT_LE(origins.size(), 8u);
  for (int v : origins)
    EXPECT_LT(mesh.vert[size_t(v)].cP().Norm(), 1.2) << "origin candidate " << v;
  // The written map from the first valid origin: degree 2, four branch points, nothing folded.
  std::vector<std::pair<std::string, double>> timings;
  StageClock clock(timings);
  const WrittenSphere written = written_genus1_map(prepared, forms, origins, true, {}, clock);
  EXPECT_GE(written.origin_attempts, 1);
  EXPECT_LE(written.origin_attempts, 4);
  EXPECT_EQ(written.branching.degree, 2);
  EXPECT_TRUE(written.branching.riemann_hurwitz_ok);
  EXPECT_EQ(written.branching.branch_vertices.size(), 4u);
  for (const MeshFace &face : unit.face)
    EXPECT_FALSE(folded_image(written.sphere[size_t(index_of(unit, face.cV(0)))],
                              written.sphere[size_t(index_of(unit, face.cV(1)))],
                              written.sphere[size_t(index_of(unit, face.cV(2)))]));
}

TEST(ZeroAreaImages, ACapsMiddleVertexMovesInsideItsNeighbours) {
  // The faces (a, m, c), (m, b, c) and the cap (a, b, m) of an octahedron's face split at the
  // midpoint m of its edge a-b, with m's image on the great circle through a and b as a map
  // would leave it: the cap's image is flat. After: every face around m is turned the right way,
  // and m moved little.
  MeshArrays arrays;
  arrays.positions = {Point3(1, 0, 0),  Point3(0, 1, 0),  Point3(0, 0, 1),    Point3(-1, 0, 0),
                      Point3(0, -1, 0), Point3(0, 0, -1), Point3(0.5, 0.5, 0)};
  // The octahedron's outward faces, (0, 1, 2) split at m = 6 on the edge 0-1, closed by the cap
  // (0, 1, 6) against the face (1, 0, 5) across that edge.
  arrays.triangles = {{0, 6, 2}, {6, 1, 2}, {0, 1, 6}, {1, 3, 2}, {3, 4, 2},
                      {4, 0, 2}, {1, 0, 5}, {3, 1, 5}, {4, 3, 5}, {0, 4, 5}};
  Mesh mesh;
  mesh_from_arrays(arrays, mesh);
  std::vector<Eigen::Vector3d> sphere;
  for (const Point3 &p : arrays.positions)
    sphere.push_back(p.ToEigenVector<Eigen::Vector3d>().normalized());
  sphere[6] = (sphere[0] + sphere[1]).normalized(); // on the great circle through a and b
  const FaceIncidence in = face_incidence(mesh);
  EXPECT_TRUE(folded_or_flat(in, sphere, 2)) << "the cap starts flat";
  const Eigen::Vector3d before = sphere[6];
  const std::vector<int> moved =
      orient_zero_area_images(mesh, {2}, std::vector<char>(7, 0), std::vector<char>(7, 0), sphere);
  EXPECT_EQ(moved, std::vector<int>{6});
  for (int f : in.faces_of_vertex[6])
    EXPECT_FALSE(folded_or_flat(in, sphere, f)) << "face " << f;
  EXPECT_LT((sphere[6] - before).norm(), 0.05);
}

TEST(MapValidity, SaysWhatFailsAndLeadsWithCollapsedFaces) {
  Parameterization map;
  map.genus = 2;
  map.euler = -2;
  map.degree = 2;
  map.ramification = 6;
  map.riemann_hurwitz_ok = true;
  EXPECT_TRUE(invalid_reasons({}, map).empty());
  map.degree = 1;
  map.riemann_hurwitz_ok = false;
  map.quality.folded_face_indices = {7};
  map.quality.collapsed_face_indices = {3, 4};
  const std::vector<std::string> reasons = invalid_reasons({}, map);
  ASSERT_EQ(reasons.size(), 4u);
  EXPECT_NE(reasons[0].find("2 faces shrink below what double precision resolves"),
            std::string::npos)
      << reasons[0];
  EXPECT_NE(reasons[1].find("covers the sphere 1 times instead of 2"), std::string::npos)
      << reasons[1];
  EXPECT_NE(reasons[2].find("Riemann-Hurwitz"), std::string::npos) << reasons[2];
  EXPECT_NE(reasons[3].find("1 face is turned over (face 7)"), std::string::npos) << reasons[3];
}

TEST(FindingHandling, WhatParamDoesWithEachFinding) {
  Finding parts(FindingKind::several_components), flat(FindingKind::zero_area_faces),
      holes(FindingKind::boundary_loops), pinch(FindingKind::non_manifold_vertices),
      seam(FindingKind::duplicate_vertices), mobius(FindingKind::non_orientable);
  seam.repairable = true;
  EXPECT_EQ(finding_handling(parts), FindingHandling::as_it_is);
  EXPECT_EQ(finding_handling(flat), FindingHandling::as_it_is);
  EXPECT_EQ(finding_handling(holes), FindingHandling::close_holes);
  EXPECT_EQ(finding_handling(pinch), FindingHandling::split_nonmanifold);
  EXPECT_EQ(finding_handling(seam), FindingHandling::set_aside);
  EXPECT_EQ(finding_handling(mobius), FindingHandling::refused);
  // --strict: what is otherwise dealt with is refused (or left to the safe repairs).
  EXPECT_EQ(finding_handling(parts, true), FindingHandling::as_it_is);
  EXPECT_EQ(finding_handling(holes, true), FindingHandling::refused);
  EXPECT_EQ(finding_handling(pinch, true), FindingHandling::refused);
  EXPECT_EQ(finding_handling(seam, true), FindingHandling::repair);
}

} // namespace
} // namespace meromorph
