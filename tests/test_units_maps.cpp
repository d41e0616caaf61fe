// Direct tests of the map's stages, each on inputs whose answer is known exactly: the one-ring
// order, Floater's embedding, the star's kernel, fold untangling, generic form pairs, the ratio
// map and the pair search, genus 1's flat corners, genus 0's correction and south cap, the parts
// map and its texture grid; the arc grid and plane triangles they rely on.
#include "stage_units.h"

namespace meromorph {
namespace {

using namespace test;

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

TEST(Genus0Correction, FoldedPlaneFacesByOrientationOnTheSphere) {
  FaceIncidence in;
  in.corners = {{0, 1, 2}, {0, 2, 1}, {3, 4, 5}};
  const std::vector<PlaneValue> values = {{{0, 0}},  {{0.5, 0}}, {{0, 0.5}},
                                          {{10, 0}}, {{0, -10}}, {{20, 0}}};
  // The second face is the first turned over; the third, far out, turns clockwise in the plane
  // but its circumcircle holds the unit disk's centre's antipode: on the sphere it is not folded.
  EXPECT_EQ(folded_plane_faces(in, values), std::vector<int>{1});
  // Against a direct computation: a plane triangle keeps its orientation on the sphere exactly
  // when 1 + |c|^2 > R^2 (c its circumcentre, R its circumradius), for triangles of every size
  // and place (200k of them; those within rounding of the circle condition left out).
  std::mt19937_64 random(7);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(-2, 2);
  FaceIncidence many;
  std::vector<PlaneValue> corners;
  std::vector<int> expected;
  for (int t = 0; t < 200000; ++t) {
    const double scale = std::pow(10.0, uniform(random));
    const Complex shift = Complex(normal(random), normal(random)) * scale * (1 + uniform(random));
    Complex z[3];
    for (Complex &w : z)
      w = Complex(normal(random), normal(random)) * scale + shift;
    const double orientation = std::imag(std::conj(z[1] - z[0]) * (z[2] - z[0]));
    const Complex a = z[0], b = z[1], c = z[2];
    const double d = 2 * (a.real() * (b.imag() - c.imag()) + b.real() * (c.imag() - a.imag()) +
                          c.real() * (a.imag() - b.imag()));
    const Complex centre(
        (std::norm(a) * (b.imag() - c.imag()) + std::norm(b) * (c.imag() - a.imag()) +
         std::norm(c) * (a.imag() - b.imag())) /
            d,
        (std::norm(a) * (c.real() - b.real()) + std::norm(b) * (a.real() - c.real()) +
         std::norm(c) * (b.real() - a.real())) /
            d);
    const double power = 1 + std::norm(centre) - std::norm(a - centre);
    if (std::abs(power) < 1e-6 * (1 + std::norm(a - centre)) || std::abs(orientation) < 1e-9)
      continue;
    const int first = int(corners.size());
    for (const Complex &w : z)
      corners.push_back({w});
    many.corners.push_back({first, first + 1, first + 2});
    if ((orientation > 0) != (power > 0)) expected.push_back(int(many.corners.size()) - 1);
  }
  ASSERT_GT(many.corners.size(), 150000u);
  EXPECT_EQ(folded_plane_faces(many, corners), expected);
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

} // namespace
} // namespace meromorph
