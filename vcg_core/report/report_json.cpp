#include "report/report_json.h"

namespace meromorph {

nlohmann::json topology_json(const Topology &topology) {
  nlohmann::json loops = nlohmann::json::array();
  for (const BoundaryLoop &loop : topology.boundary_loops)
    loops.push_back({{"vertex", loop.first_vertex}, {"edges", loop.length}});
  return {
      {"vertices", topology.vertices},
      {"edges", topology.edges},
      {"faces", topology.faces},
      {"components", topology.component_faces.size()},
      {"component_faces", topology.component_faces},
      {"boundary_loops", loops},
      {"non_manifold_edges", topology.non_manifold_edges},
      {"euler", topology.euler},
      {"orientable", topology.orientable},
      {"genus", topology.genus ? nlohmann::json(*topology.genus) : nlohmann::json(nullptr)},
  };
}

nlohmann::json remedies_json(const std::vector<Remedy> &remedies) {
  nlohmann::json codes = nlohmann::json::array();
  for (Remedy remedy : remedies)
    codes.push_back(remedy_code(remedy));
  return codes;
}

nlohmann::json findings_json(const Validation &validation) {
  nlohmann::json findings = nlohmann::json::array();
  for (const Finding &f : validation.findings) {
    nlohmann::json edges = nlohmann::json::array();
    for (const auto &edge : f.edges)
      edges.push_back({edge[0], edge[1]});
    findings.push_back({{"code", finding_code(f.kind)},
                        {"message", f.message},
                        {"repairable", f.repairable},
                        {"remedies", remedies_json(f.remedies)},
                        {"vertices", f.vertices},
                        {"edges", edges},
                        {"faces", f.faces},
                        {"sizes", f.sizes}});
  }
  return findings;
}

nlohmann::json source_json(const MeshSource &source) {
  return {{"path", source.path}, {"format", format_name(source.format)}, {"notes", source.notes}};
}

nlohmann::json complex_matrix_json(const Eigen::MatrixXcd &matrix) {
  nlohmann::json rows = nlohmann::json::array();
  for (long i = 0; i < matrix.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (long j = 0; j < matrix.cols(); ++j)
      row.push_back({matrix(i, j).real(), matrix(i, j).imag()});
    rows.push_back(row);
  }
  return rows;
}

namespace {

nlohmann::json statistics_json(const QualityStatistics &s) {
  return {{"faces", s.faces},
          {"quasi_conformal_mean", s.quasi_conformal_mean},
          {"quasi_conformal_p95", s.quasi_conformal_p95},
          {"quasi_conformal_max", s.quasi_conformal_max},
          {"angle_error_mean_degrees", s.angle_error_mean_degrees},
          {"folded_faces", s.folded_faces},
          {"collapsed_faces", s.collapsed_faces}};
}

nlohmann::json vector_json(const Eigen::Vector3d &v) {
  return {v[0], v[1], v[2]};
}

// Branch points with their vertex, position, sphere point and local degree.
nlohmann::json branch_points_json(const Parameterization &map) {
  nlohmann::json branch_points = nlohmann::json::array();
  for (const BranchPoint &b : map.branch_points) {
    branch_points.push_back({{"vertex", b.vertex},
                             {"position", vector_json(b.position)},
                             {"sphere", vector_json(b.sphere)},
                             {"local_degree", b.local_degree},
                             {"ramification", b.local_degree}}); // the old name, for one release
    if (b.sphere_vertex >= 0) branch_points.back()["sphere_vertex"] = b.sphere_vertex;
  }
  return branch_points;
}

// Several parts or closed holes: each part's own report, their spacing, the holes closed.
void add_parts_json(const Parameterization &map, nlohmann::json &report) {
  nlohmann::json components = nlohmann::json::array();
  for (const Parameterization &part : map.components) {
    nlohmann::json entry = parameterization_json(part);
    entry["faces"] = part.quality.overall.faces;
    entry.erase("timings_ms");
    components.push_back(entry);
  }
  report["components"] = components;
  report["component_spacing"] = map.component_spacing;
  nlohmann::json holes = nlohmann::json::array();
  for (const ClosedHoleReport &hole : map.holes_closed)
    holes.push_back({{"part", hole.part},
                     {"edges", hole.edges},
                     {"vertex", hole.vertex},
                     {"sphere_area_over_4pi", hole.image_area_over_4pi}});
  report["holes_closed"] = holes;
}

// Genus >= 2: the pair of forms and how many pairs were tried.
void add_form_pair_json(const Parameterization &map, nlohmann::json &report) {
  report["form_pair"] = map.form_pair;
  auto coefficients = [](const Eigen::VectorXcd &c) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto &value : c)
      list.push_back({value.real(), value.imag()});
    return list;
  };
  report["form_coefficients"] = {{"a", coefficients(map.form_coefficients.first)},
                                 {"b", coefficients(map.form_coefficients.second)}};
  report["pair_attempts"] = map.pair_attempts;
}

} // namespace

nlohmann::json area_correction_json(const AreaCorrection &correction) {
  return {{"applied", correction.applied},
          {"area_distortion_before", correction.distortion_before},
          {"area_distortion_after", correction.distortion_after},
          {"ball_translation", vector_json(correction.translation)}};
}

nlohmann::json remesh_json(const SurfaceRemesh &remesh) {
  const RemeshQuality &q = remesh.quality;
  nlohmann::json parts = nlohmann::json::array();
  for (const RemeshPart &part : remesh.parts)
    parts.push_back({{"frequency", part.frequency},
                     {"degree", part.degree},
                     {"ramification", part.ramification},
                     {"target_vertices", part.target_vertices}});
  nlohmann::json valence = nlohmann::json::array();
  for (const auto &[count, vertices] : q.valence_histogram)
    valence.push_back({count, vertices});
  nlohmann::json sparse = nlohmann::json::array();
  for (const SparseRegion &region : remesh.sparse_regions)
    sparse.push_back({{"faces", region.faces},
                      {"area_share", region.area_share},
                      {"sample_share", region.sample_share},
                      {"vertex", region.vertex}});
  return {{"vertices", q.vertices},
          {"edges", q.edges},
          {"faces", q.faces},
          {"euler", q.euler},
          {"target_vertices", remesh.target_vertices},
          {"parts", parts},
          {"boundary_edges", q.boundary_edges},
          {"nonmanifold_edges", q.nonmanifold_edges},
          {"nonmanifold_vertices", q.nonmanifold_vertices},
          {"unlifted_faces", remesh.unlifted_faces},
          {"unclosed_faces", remesh.unclosed_faces},
          {"folded_lifts", remesh.folded_lifts},
          {"hausdorff_over_diagonal",
           {{"to_input", q.hausdorff_to_input}, {"from_input", q.hausdorff_from_input}}},
          {"mean_distance_over_diagonal",
           {{"to_input", q.mean_distance_to_input}, {"from_input", q.mean_distance_from_input}}},
          {"angles_degrees",
           {{"min", q.min_angle_degrees},
            {"mean", q.mean_angle_degrees},
            {"min_away_from_branch_vertices", q.min_angle_away_from_branch_degrees}}},
          {"valence_histogram", valence},
          {"sparsely_sampled_regions", sparse}};
}

nlohmann::json parameterization_json(const Parameterization &map) {
  nlohmann::json timings = nlohmann::json::object();
  for (const auto &[stage, ms] : map.timings_ms) // a stage run more than once: its total
    timings[stage] = timings.value(stage, 0.0) + ms;
  nlohmann::json report = {
      {"genus", map.genus},
      {"euler", map.euler},
      {"degree", map.degree},
      {"vertices", map.uv.vertex.size()}, // the surface as written
      {"faces", map.uv.wedge.size()},
      {"image_area_over_4pi", map.area_over_4pi},
      {"method", map.method},
      {"branch_points", branch_points_json(map)},
      {"ramification_total", map.ramification},
      {"snapped_branch_points", map.snapped_branch_points},
      {"untangled_vertices", map.untangled_vertices},
      {"riemann_hurwitz_ok", map.riemann_hurwitz_ok},
      {"layers",
       {{"count", map.sheets.count},
        {"coverage", map.sheets.coverage},
        {"cut_faces", map.sheets.cut_faces}}},
      {"mobius",
       {{"applied", map.mobius_applied},
        {"centroid_before", vector_json(map.mobius.centroid_before)},
        {"centroid_after", vector_json(map.mobius.centroid_after)},
        {"newton_steps", map.mobius.steps}}},
      {"distortion",
       {{"overall", statistics_json(map.quality.overall)},
        {"away_from_branch_points", statistics_json(map.quality.away_from_branch_points)}}},
      {"non_holomorphicity_mean", map.non_holomorphicity_mean},
      {"timings_ms", timings}};
  // With several parts the genus-specific figures are the parts' (in `components`).
  const bool one_part = map.components.size() <= 1;
  if (map.modulus) report["modulus"] = {map.modulus->real(), map.modulus->imag()};
  if (one_part && map.genus >= 2)
    report["riemann_matrix"] = complex_matrix_json(map.riemann_matrix);
  if (one_part && map.genus == 0)
    report["genus0"] = {{"pole_face", map.pole_face},
                        {"weights", map.intrinsic_delaunay ? "intrinsic Delaunay" : "cotangent"},
                        {"raised_weights", map.raised_weights}};
  if (one_part && map.genus == 1) {
    report["origin_vertex"] = map.origin_vertex;
    report["origin_attempts"] = map.origin_attempts;
  }
  if (map.area_correction.applied || map.area_correction.distortion_before > 0)
    report["area_correction"] = area_correction_json(map.area_correction);
  report["valid"] = map.valid;
  report["invalid"] = map.invalid;
  if (!map.advice.empty()) {
    nlohmann::json advice = nlohmann::json::array();
    for (const Advice &a : map.advice)
      advice.push_back({{"cause", a.cause}, {"remedy", remedy_code(a.remedy)}});
    report["advice"] = advice;
  }
  report["notes"] = map.notes;
  if (!map.components.empty()) add_parts_json(map, report);
  if (!map.sphere_source_vertex.empty()) {
    nlohmann::json edges = nlohmann::json::array();
    for (const auto &edge : map.nonmanifold_split.edges)
      edges.push_back({edge[0], edge[1]});
    report["nonmanifold_split"] = {{"vertices", map.nonmanifold_split.vertices},
                                   {"edges", edges},
                                   {"added_vertices", map.nonmanifold_split.added_vertices}};
  }
  if (map.computed_on_refinement > 0) report["computed_on_refinement"] = map.computed_on_refinement;
  if (!map.added_vertices.empty()) {
    // Each added vertex: its index in the written surface, the input's face it lies on, its
    // barycentric coordinates there (of the face's second and third corners) and its position.
    nlohmann::json added = nlohmann::json::array();
    const size_t first = map.sphere.size() - map.added_vertices.size();
    for (size_t k = 0; k < map.added_vertices.size(); ++k) {
      const AddedVertex &v = map.added_vertices[k];
      added.push_back({{"vertex", first + k},
                       {"face", v.face},
                       {"b1", v.b1},
                       {"b2", v.b2},
                       {"position", {v.position[0], v.position[1], v.position[2]}}});
    }
    report["added_vertices"] = added;
    report["written_faces"] = map.surface_faces.size();
  }
  if (one_part && map.genus >= 2) add_form_pair_json(map, report);
  return report;
}

std::string json_text(const nlohmann::json &report) {
  return report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

nlohmann::json holomorphic_forms_json(const HolomorphicForms &forms, SolverKind solver) {
  nlohmann::json timings = nlohmann::json::object();
  for (const auto &[stage, ms] : forms.timings_ms)
    timings[stage] = ms;
  nlohmann::json symplectic = nlohmann::json::array();
  for (Eigen::Index row = 0; row < forms.symplectic.rows(); ++row) {
    nlohmann::json cells = nlohmann::json::array();
    for (Eigen::Index column = 0; column < forms.symplectic.cols(); ++column)
      cells.push_back(forms.symplectic(row, column));
    symplectic.push_back(cells);
  }
  nlohmann::json report = {
      {"genus", forms.genus},
      {"euler", 2 - 2 * forms.genus},
      {"solver", solver_name(solver)},
      {"loop_periods", complex_matrix_json(forms.loop_periods)},
      {"a_periods", complex_matrix_json(forms.a_periods)},
      {"b_periods", complex_matrix_json(forms.b_periods)},
      {"symplectic_basis", symplectic},
      {"residuals",
       {{"closedness", forms.closedness_residual},
        {"coclosedness", forms.coclosedness_residual},
        {"conjugate_fit", forms.conjugate_residual},
        {"intersection_rounding", forms.wedge_rounding}}},
      {"non_holomorphicity",
       {{"mean", forms.non_holomorphicity_mean}, {"max", forms.non_holomorphicity_max}}},
      {"timings_ms", timings}};
  if (forms.modulus) report["modulus"] = {forms.modulus->real(), forms.modulus->imag()};
  if (forms.genus >= 2) report["riemann_matrix"] = complex_matrix_json(forms.riemann_matrix);
  return report;
}

const std::string &match_method(const SurfaceMatch &match) {
  return match.genus == 1 ? match.torus.method : match.alignment.method;
}

// How the source's image was put on the target's: the sphere's rotation or the tori's lattice map.
nlohmann::json match_alignment_json(const SurfaceMatch &match) {
  nlohmann::json alternatives = nlohmann::json::array();
  if (match.genus == 1) {
    const auto matrix = [](const Eigen::Matrix2i &m) {
      return nlohmann::json{{m(0, 0), m(0, 1)}, {m(1, 0), m(1, 1)}};
    };
    for (const auto &alternative : match.torus.alternatives)
      alternatives.push_back({{"lattice_map", matrix(alternative.lattice_map)},
                              {"shift", {alternative.shift[0], alternative.shift[1]}},
                              {"cost", alternative.cost}});
    return {{"lattice_map", matrix(match.torus.lattice_map)},
            {"shift", {match.torus.shift[0], match.torus.shift[1]}},
            {"dilatation", match.torus.dilatation},
            {"cost", match.torus.cost},
            {"alternatives", alternatives},
            {"landmark_flat_distance_max", match.torus.landmark_distance_max}};
  }
  if (match.genus == 2) { // the Moebius transformation of the branch values, and the sheets
    for (const auto &alternative : match.alignment.alternatives)
      alternatives.push_back({{"cost", alternative.cost}});
    return {{"cost", match.alignment.cost},
            {"alternatives", alternatives},
            {"branch_value_distance_max", match.alignment.landmark_distance_max}};
  }
  for (const auto &alternative : match.alignment.alternatives)
    alternatives.push_back({{"angle_from_best_degrees", alternative.angle_from_best_degrees},
                            {"cost", alternative.cost}});
  return {{"cost", match.alignment.cost},
          {"alternatives", alternatives},
          {"landmark_sphere_distance_max", match.alignment.landmark_distance_max}};
}

nlohmann::json match_json(const SurfaceMatch &match, size_t landmark_count) {
  nlohmann::json timings = nlohmann::json::object();
  for (const auto &[stage, ms] : match.timings_ms)
    timings[stage] = ms;
  nlohmann::json report = {{"genus", match.genus},
                           {"method", match_method(match)},
                           {"alignment", match_alignment_json(match)},
                           {"landmarks",
                            {{"count", landmark_count},
                             {"residual_mean", match.landmark_residual_mean},
                             {"residual_max", match.landmark_residual_max}}},
                           {"matched_mesh",
                            {{"angle_error_mean_degrees", match.angle_error_mean_degrees},
                             {"folded_faces", match.folded_faces},
                             {"unmatched_vertices", match.unmatched_vertices}}},
                           {"timings_ms", timings}};
  if (match.genus == 1)
    report["moduli"] = {{"source", {match.source_modulus.real(), match.source_modulus.imag()}},
                        {"target", {match.target_modulus.real(), match.target_modulus.imag()}}};
  if (match.round_trip_mean >= 0)
    report["round_trip"] = {{"mean", match.round_trip_mean}, {"max", match.round_trip_max}};
  return report;
}

} // namespace meromorph
