#include "maps/parameterization.h"

#include "common/errors.h"
#include "common/stage_clock.h"
#include "common/wording.h"
#include "forms/holomorphic_pipeline.h"
#include "maps/added_vertices.h"
#include "maps/form_pair_search.h"
#include "maps/genus0_best_map.h"
#include "maps/genus1_map.h"
#include "maps/map_validity.h"
#include "maps/written_map.h"
#include "mesh/edge_splitting.h"
#include "mesh/face_vectors.h"
#include "mesh/mesh_from_arrays.h"
#include "mesh/prepared_mesh.h"
#include "mesh/unit_scale.h"
#include "mesh/validation.h"
#include "sphere/area_correction.h"

namespace meromorph {
namespace {

void adopt(WrittenSphere &&written, Parameterization &out, Branching &branching) {
  out.sphere = std::move(written.sphere);
  out.mobius = written.mobius;
  out.mobius_applied = written.mobius_applied;
  out.snapped_branch_points = written.snapped_branch_points;
  out.untangled_vertices = written.untangled_vertices;
  if (written.origin_vertex >= 0) {
    out.origin_vertex = written.origin_vertex;
    out.origin_attempts = written.origin_attempts;
  }
  branching = std::move(written.branching);
  out.flat = std::move(written.flat);
}

// Branch points, sheets and layers, texture coordinates, distortion and validity of the map as
// written.
void describe_written_map(const std::vector<Point3> &input_positions, const Mesh &mesh,
                          const MeshEdges &edges, const ParameterizeOptions &options,
                          const Branching &branching, Parameterization &out,
                          const Progress &progress, StageClock &clock) {
  out.degree = branching.degree;
  out.area_over_4pi = branching.area_over_4pi;
  out.ramification = branching.ramification;
  out.riemann_hurwitz_ok = branching.riemann_hurwitz_ok;
  out.branch_flag.assign(mesh.vert.size(), 0);
  for (int v : branching.branch_vertices) {
    out.branch_points.push_back({v, input_positions[size_t(v)].ToEigenVector<Eigen::Vector3d>(),
                                 out.sphere[v], branching.local_degree[v]});
    out.branch_flag[v] = branching.local_degree[v];
  }
  out.sheets = label_sheets(mesh, edges, out.sphere, branching.branch_vertices, out.degree);
  out.layered = out.sphere;
  for (size_t v = 0; v < out.layered.size(); ++v)
    out.layered[v] *= 1.0 + options.layer_gap * out.sheets.vertex_layer[v];
  clock.done("branching");

  progress.report(0.9, "texture coordinates and distortion");
  out.uv = texture_coordinates(mesh, out.sphere, options.uv_kind);
  out.quality = measure_map_quality(mesh, out.sphere, branching.branch_vertices);
  out.invalid = invalid_reasons(options, out);
  out.valid = out.invalid.empty();
  if (!out.valid) out.advice = invalid_map_advice(input_positions, mesh, options, out);
  clock.done("texture_and_quality");
}

// Genus 0: the harmonic map with a pole, on the sphere.
WrittenSphere written_genus0_map(const PreparedMesh &prepared, const ParameterizeOptions &options,
                                 Parameterization &out, const Progress &progress,
                                 StageClock &clock) {
  const Genus0Result map = best_genus0_map(prepared, options.solver, options.pole_face);
  out.pole_face = map.pole_face;
  out.raised_weights = map.raised_weights;
  out.intrinsic_delaunay = map.intrinsic_delaunay;
  out.method = map.intrinsic_delaunay
                   ? "genus 0: harmonic map with a simple pole (intrinsic Delaunay weights), "
                     "inverse stereographic projection"
                   : "genus 0: harmonic map with a simple pole (cotangent weights, raised to "
                     "positive ones near folds), inverse stereographic projection";
  clock.done("meromorphic");
  WrittenSphere written;
  finish_on_sphere(prepared, options.mobius, nullptr, out.euler, map.values, nullptr, &map.centred,
                   written, progress, clock);
  return written;
}

// Genus 1: P of the flat coordinate, its double pole on the chosen or the best origin.
WrittenSphere written_genus1(const PreparedMesh &prepared, const HolomorphicForms &forms,
                             const ParameterizeOptions &options, Parameterization &out,
                             const Progress &progress, StageClock &clock) {
  out.modulus = forms.modulus;
  out.riemann_matrix = forms.riemann_matrix;
  const std::vector<int> origins =
      options.origin_vertex >= 0
          ? std::vector<int>{options.origin_vertex}
          : genus1_origin_candidates(prepared, forms.normalized[0],
                                     WeierstrassP(Complex(1, 0), forms.riemann_matrix(0, 0)));
  out.method = "genus 1: Weierstrass P-function of the flat coordinate";
  out.flat_periods = WeierstrassP(Complex(1, 0), forms.riemann_matrix(0, 0)).periods();
  clock.done("meromorphic");
  return written_genus1_map(prepared, forms, origins, options.mobius, progress, clock);
}

// Genus g >= 2: the ratio of the best pair of forms, on the sphere.
WrittenSphere written_form_ratio(const PreparedMesh &prepared, const HolomorphicForms &forms,
                                 const ParameterizeOptions &options, Parameterization &out,
                                 const Progress &progress, StageClock &clock) {
  out.riemann_matrix = forms.riemann_matrix;
  out.form_pair = options.form_pair;
  PairSearch search =
      search_form_pairs(prepared, forms, options.form_pair, options.mobius, progress);
  out.form_coefficients = search.coefficients;
  out.pair_attempts = search.attempts;
  out.method = "genus " + std::to_string(out.genus) +
               ": ratio (omega1 + omega2) / (omega1 - omega2), omega1 = sum a_k psi_k, "
               "omega2 = sum b_k psi_k of the normalized holomorphic 1-forms psi_k (a_k, b_k: "
               "form_coefficients)";
  clock.done("meromorphic");
  WrittenSphere written;
  written.mobius = search.centring;
  written.mobius_applied = options.mobius;
  written.snapped_branch_points = search.snapped_branch_points;
  written.untangled_vertices = search.untangled_vertices;
  finish_on_sphere(prepared, options.mobius, nullptr, out.euler, std::move(search.values),
                   &search.branching, nullptr, written, progress, clock);
  return written;
}

// After centring, the Moebius transformation that spreads the map most evenly in area.
void correct_the_area(const Mesh &mesh, Parameterization &out, Branching &branching,
                      StageClock &clock) {
  out.area_correction = correct_area(mesh, out.sphere, branching.degree);
  if (out.area_correction.applied) {
    out.mobius.transformation =
        translation_matrix(out.area_correction.translation).after(out.mobius.transformation);
    branching = analyse_branching(mesh, out.sphere, out.euler);
  }
  clock.done("area_correction");
}

// The map computed on `mesh` refined (fine, whose first vertices and face slots are mesh's),
// said on mesh's own vertices: their values, the branching and all that follows measured anew on
// mesh's faces.
Parameterization restricted_to(const std::vector<Point3> &positions, const Mesh &mesh,
                               const MeshEdges &edges, const ParameterizeOptions &options,
                               Parameterization fine, const SplitEdges &refined,
                               const Progress &progress, StageClock &clock) {
  Parameterization out = std::move(fine);
  out.sphere.resize(mesh.vert.size());
  if (!out.flat.empty()) out.flat.resize(mesh.vert.size());
  out.branch_points.clear();
  out.advice.clear();
  if (out.pole_face >= 0) out.pole_face = refined.face_source[size_t(out.pole_face)];
  if (out.origin_vertex >= int(mesh.vert.size())) out.origin_vertex = -1;
  const Branching branching = analyse_branching(mesh, out.sphere, out.euler);
  describe_written_map(positions, mesh, edges, options, branching, out, progress, clock);
  return out;
}

// The map computed on the mesh refined (split_long_edges) at the `level`th finer edge length.
struct FinerMap {
  int level = 0;
  SplitEdges refined;
  Parameterization map;
};

// When the map on the mesh's own triangulation is not valid: the map on the mesh refined until
// no edge is longer than that of an even triangulation with 4, 16, 64 (up to options.finer_levels
// powers of 4) times its vertices (long thin faces become many well-shaped ones; within a budget
// of faces), from the first that carries a valid one; none when none does.
std::optional<FinerMap> finer_map(Mesh &mesh, const ParameterizeOptions &options,
                                  const Progress &progress, StageClock &clock) {
  constexpr size_t face_budget = size_t(4) << 20;
  const MeshArrays arrays = arrays_from_mesh(mesh);
  const double area = vcg::tri::Stat<Mesh>::ComputeMeshArea(mesh);
  for (int level = 1; level <= options.finer_levels; ++level) {
    // An equilateral triangulation of this area with n vertices has edges sqrt(area / 0.866 n).
    const double vertices = double(arrays.positions.size()) * std::pow(4.0, level);
    progress.report(0.0, "the triangulation cannot carry the map: computing on it refined");
    std::optional<SplitEdges> refined =
        split_long_edges(arrays, std::sqrt(area / (0.866 * vertices)), face_budget);
    if (!refined) break;
    FinerMap finer{level, std::move(*refined), {}};
    Mesh fine;
    mesh_from_arrays(finer.refined.arrays, fine);
    ParameterizeOptions fine_options = options;
    fine_options.finer_levels = 0;
    fine_options.add_vertices = false;
    finer.map = parameterize(fine, fine_options, progress);
    clock.done("finer_computation");
    if (finer.map.valid) return finer;
  }
  return std::nullopt;
}

// The written surface with vertices added: the map of `surface` (whose first vertices are
// mesh's, whose faces are parts of mesh's faces `face_source`), with its added vertices' places
// on mesh, their positions and the branch points' in the caller's unit.
void with_added_vertices(const Mesh &mesh, const std::vector<Point3> &positions,
                         const MeshArrays &surface, const std::vector<int> &face_source,
                         Parameterization &map) {
  map.added_vertices = places_on(mesh, positions, surface, face_source);
  for (BranchPoint &b : map.branch_points)
    b.position = size_t(b.vertex) < mesh.vert.size()
                     ? positions[size_t(b.vertex)].ToEigenVector<Eigen::Vector3d>()
                     : map.added_vertices[size_t(b.vertex) - mesh.vert.size()].position;
  map.surface_faces = surface.triangles;
  map.surface_face_source = face_source;
  map.notes.push_back(plural(map.added_vertices.size(), "vertex was", "vertices were") +
                      " added to the written surface where its own faces could not carry the "
                      "map without turning over (listed with their faces)");
}

// Where the map turns faces of the mesh over: the mesh cut there (added_vertices.h) and mapped
// again, as long as the folded faces get fewer, up to four times. The map of the cut mesh, or
// none.
std::optional<Parameterization> mapped_with_cuts(const std::vector<Point3> &positions, Mesh &mesh,
                                                 const ParameterizeOptions &options,
                                                 Parameterization map, int levels,
                                                 const Progress &progress) {
  ParameterizeOptions cut_options = options;
  cut_options.add_vertices = false;
  cut_options.finer_levels = std::max(levels, 1);
  SplitEdges cut = split_edges(arrays_from_mesh(mesh), {}); // nothing cut yet
  Mesh cut_mesh;
  const Mesh *mapped = &mesh;
  for (int round = 0; round < 4; ++round) {
    const std::vector<std::array<int, 2>> sides = sides_to_cut(*mapped, map);
    if (sides.empty()) return std::nullopt;
    cut_sides(cut, sides);
    mesh_from_arrays(cut.arrays, cut_mesh);
    mapped = &cut_mesh;
    progress.report(0.0, "adding vertices where the map turns faces over");
    const size_t folds = map.quality.folded_face_indices.size();
    map = parameterize(cut_mesh, cut_options, progress);
    if (map.valid) {
      with_added_vertices(mesh, positions, cut.arrays, cut.face_source, map);
      return map;
    }
    if (map.quality.folded_face_indices.size() >= folds) return std::nullopt;
  }
  return std::nullopt;
}

// No refinement carried a valid map either: refining by hand would not help; a new
// triangulation (isotropic remeshing) may.
void advise_remeshing_after_refinement(Parameterization &out) {
  for (Advice &advice : out.advice)
    if (advice.remedy == Remedy::refine)
      advice = {"no refinement of the mesh that meromorph tried carried a valid map either",
                Remedy::remesh};
}

// When the map on the mesh's own triangulation is not valid: the finer map carried back to its
// vertices; where that turns faces over (and options.add_vertices), the mesh cut there and mapped
// again, or else the finer map on the whole refined mesh.
void map_finer(const std::vector<Point3> &positions, Mesh &mesh, const MeshEdges &edges,
               const ParameterizeOptions &options, Parameterization &out, const Progress &progress,
               StageClock &clock) {
  std::optional<FinerMap> finer = finer_map(mesh, options, progress, clock);
  if (finer) {
    const std::vector<std::pair<std::string, double>> timings = out.timings_ms;
    out =
        restricted_to(positions, mesh, edges, options, finer->map, finer->refined, progress, clock);
    out.timings_ms = timings;
    out.computed_on_refinement = finer->level;
    out.notes.push_back("computed on the mesh refined (" +
                        std::to_string(finer->refined.arrays.positions.size()) +
                        " vertices: its long edges cut at their midpoints until none was longer "
                        "than an even triangulation's): its own triangulation could not carry a "
                        "valid map");
  }
  if (out.valid) return;
  if (!options.add_vertices) {
    // The refinement carried a valid map; the mesh's own faces cannot: vertices would do.
    if (finer)
      out.advice = {{"the map was computed on the mesh refined (" +
                         std::to_string(finer->refined.arrays.positions.size()) +
                         " vertices), and the mesh's own faces cannot carry it",
                     Remedy::add_vertices}};
    else
      advise_remeshing_after_refinement(out);
    return;
  }
  if (auto cut =
          mapped_with_cuts(positions, mesh, options, out, finer ? finer->level : 0, progress)) {
    out = std::move(*cut);
    return;
  }
  if (!finer) {
    advise_remeshing_after_refinement(out);
    return;
  }
  // The finer map as it is, on the refined mesh: every vertex the refinement made added.
  Parameterization subdivided = std::move(finer->map);
  subdivided.computed_on_refinement = finer->level;
  with_added_vertices(mesh, positions, finer->refined.arrays, finer->refined.face_source,
                      subdivided);
  subdivided.notes.push_back("the surface is written as the map was computed, refined: fewer "
                             "added vertices did not carry it");
  out = std::move(subdivided);
}

} // namespace

Parameterization parameterize(Mesh &mesh, const ParameterizeOptions &options,
                              const Progress &progress, const Validation *validated) {
  // The mesh is validated once: by the caller, or by compute_holomorphic_forms below.
  if (!(options.layer_gap >= 0 && options.layer_gap <= 1e6))
    throw ArgumentError("the layer gap must be a number from 0 to 1e6");
  // Everything is computed at unit scale (unit_scale.h): the mesh itself is moved there and put
  // back when this returns or throws; positions reported are the input's.
  const UnitScaleInPlace unit(mesh);
  const Validation validation = validated ? *validated : validate_mesh(mesh);
  if (!validation.ok()) throw refusal(validation.main_finding());

  Parameterization out;
  StageClock clock(out.timings_ms);
  progress.report(0.0, "edges and cotangent weights");
  // Every stage below reads it; the forms only its edges: the rest is prepared after them.
  PreparedMesh prepared = prepare_mesh_edges(mesh);
  clock.done("prepare");
  HolomorphicForms forms =
      compute_holomorphic_forms(prepared, options.solver, progress.range(0.0, 0.6));
  release_intermediates(forms);
  out.timings_ms.insert(out.timings_ms.end(), forms.timings_ms.begin(), forms.timings_ms.end());
  clock.restart();
  prepare_the_rest(prepared);
  clock.done("prepare");
  out.notes = validation.notes;
  out.genus = forms.genus;
  out.euler = 2 - 2 * out.genus;
  out.non_holomorphicity_mean = forms.non_holomorphicity_mean;

  progress.report(0.6, "meromorphic function");
  WrittenSphere written =
      out.genus == 0   ? written_genus0_map(prepared, options, out, progress, clock)
      : out.genus == 1 ? written_genus1(prepared, forms, options, out, progress, clock)
                       : written_form_ratio(prepared, forms, options, out, progress, clock);
  Branching branching;
  adopt(std::move(written), out, branching);
  if (options.area_correct) correct_the_area(mesh, out, branching, clock);
  describe_written_map(unit.originals(), mesh, prepared.edges, options, branching, out, progress,
                       clock);
  if (!out.valid && out.quality.collapsed_face_indices.empty() && options.finer_levels > 0)
    map_finer(unit.originals(), mesh, prepared.edges, options, out, progress, clock);
  progress.report(1.0, "done");
  return out;
}

} // namespace meromorph
