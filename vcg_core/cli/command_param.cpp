// `meromorph param INPUT -o OUT.ply [--sphere SPHERE.ply] [--report REPORT.json] ...`: the
// conformal map onto the sphere, written as texture coordinates, a layered sphere and a JSON
// report.
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cli/exit_codes.h"
#include "cli/remedy_words.h"
#include "commands.h"
#include "common/errors.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"
#include "io/staged_outputs.h"
#include "job/map_files.h"
#include "job/surface_map.h"
#include "job_input.h"
#include "maps/parameterization.h"
#include "mesh/mesh_from_arrays.h"
#include "mesh/repair.h"
#include "own_peak_memory.h"
#include "report/report_json.h"
#include "terminal_progress.h"

namespace meromorph::cli {
namespace {

struct ParamOptions {
  std::string input, output, sphere, report;
  std::string uv = "spherical";
  std::string solver = "cholmod";
  bool no_mobius = false, repair = false, keep_invalid = false, close_holes = false,
       pack_uv = false, split_nonmanifold = false, quiet = false, area_correct = false,
       strict = false, without_uv = false, no_added_vertices = false;
  int origin = -1;
  std::vector<int> forms{-1, -1};
  double layer_gap = 0.0;
  int pole_face = -1;
};

// The core's options from the command line's.
ParameterizeOptions settings_from(const ParamOptions &options) {
  ParameterizeOptions settings;
  settings.uv_kind = options.uv == "stereographic" ? UvKind::stereographic : UvKind::spherical;
  settings.mobius = !options.no_mobius;
  settings.origin_vertex = options.origin;
  settings.form_pair = {options.forms[0], options.forms[1]};
  settings.layer_gap = options.layer_gap;
  settings.pole_face = options.pole_face;
  settings.solver = solver_from_name(options.solver);
  settings.pack_uv = options.pack_uv;
  settings.area_correct = options.area_correct;
  settings.add_vertices = !options.no_added_vertices;
  // --strict refuses what is otherwise dealt with, except what an option asks for.
  if (options.strict) {
    refuse_instead(settings);
    settings.close_holes = options.close_holes;
    settings.split_nonmanifold = options.split_nonmanifold;
  }

  return settings;
}

// The one-line summary.
// "part 0: genus 0, degree 1; part 1: genus 1, degree 2, 4 branch points" for several parts.
std::string parts_words(const Parameterization &map) {
  std::ostringstream words;
  for (size_t k = 0; k < map.components.size(); ++k) {
    const Parameterization &part = map.components[k];
    words << (k ? "; " : "") << "part " << k << ": genus " << part.genus << ", degree "
          << part.degree;
    if (!part.branch_points.empty()) words << ", " << part.branch_points.size() << " branch points";
  }
  return words.str();
}

// One line: the topology, the branching, the layers; distortion where the map is conformal
// (away from branch points, where it cannot be), with the worst faces' figure beside the mean;
// folded faces; the time.
std::string summary_line(const std::string &input, const Parameterization &map, double total_ms) {
  const QualityStatistics &away = map.quality.away_from_branch_points;
  std::ostringstream line;
  line << std::fixed << std::setprecision(2) << input << ": ";
  if (map.components.size() > 1)
    line << map.components.size() << " parts, each mapped on its own (" << parts_words(map)
         << "); in all: ";
  line << "genus " << map.genus << ", degree " << map.degree << ", " << map.branch_points.size()
       << " branch points (ramification " << map.ramification << "), Riemann-Hurwitz "
       << (map.riemann_hurwitz_ok ? "holds" : "FAILS") << ", " << map.sheets.count
       << (map.sheets.count == 1 ? " layer" : " layers");
  if (!map.added_vertices.empty())
    line << ", " << map.added_vertices.size()
         << (map.added_vertices.size() == 1 ? " vertex" : " vertices")
         << " added to the surface where its faces could not carry the map";
  line << "; away from branch points: angle error " << away.angle_error_mean_degrees
       << " deg, quasi-conformal mean " << away.quasi_conformal_mean << " (95th percentile "
       << away.quasi_conformal_p95 << "); folded faces " << away.folded_faces
       << " away from branch points (" << map.quality.overall.folded_faces << " in all); "
       << std::setprecision(0) << total_ms << " ms";
  return line.str();
}

// The map through the C++ entry on plain arrays (job/surface_map.h), as the C ABI calls it.
Parameterization map_of(const Mesh &mesh, const ParameterizeOptions &settings,
                        const Progress &progress) {
  const MeshArrays arrays = arrays_from_mesh(mesh);
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> V(arrays.positions.size(), 3);
  for (size_t v = 0; v < arrays.positions.size(); ++v)
    for (int k = 0; k < 3; ++k)
      V(Eigen::Index(v), k) = arrays.positions[v][k];
  Eigen::Matrix<int32_t, Eigen::Dynamic, 3, Eigen::RowMajor> F(arrays.triangles.size(), 3);
  for (size_t f = 0; f < arrays.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k)
      F(Eigen::Index(f), k) = arrays.triangles[f][k];
  return parameterize_arrays(V, F, settings, progress);
}

int run_param(const ParamOptions &options) {
  // Every output is checked before any work and written only when the whole job succeeded.
  StagedOutputs outputs({options.input});
  const MeshFormat surface_format = output_format(options.output);
  if (surface_format == MeshFormat::stl && !options.without_uv)
    throw ArgumentError(options.output +
                        ": an STL file cannot hold texture coordinates, which are the map: write "
                        ".ply (or .obj, .off), or give --without-uv to write the surface anyway");
  const std::string output_file = outputs.add(options.output);
  const std::string sphere_file = options.sphere.empty() ? "" : outputs.add(options.sphere);
  const std::string report_file = options.report.empty() ? "" : outputs.add(options.report);
  if (!options.sphere.empty() && output_format(options.sphere) != MeshFormat::ply)
    throw ArgumentError(options.sphere + ": the layered sphere is written as PLY (.ply)");
  if (options.forms.size() != 2) throw ArgumentError("--forms takes two indices, like --forms 0,1");

  const ParameterizeOptions settings = settings_from(options);
  const auto start = std::chrono::steady_clock::now();
  Mesh mesh;
  const JobInput input = read_job_input(options.input, options.repair, mesh);

  TerminalProgress bar(options.quiet);
  const Parameterization map =
      naming_the_input(input.source, [&] { return map_of(mesh, settings, bar.progress()); });
  bar.finish();
  if (!map.valid) {
    std::cerr << "meromorph: error: " << options.input
              << ": no valid map on this triangulation: " << join_phrases(map.invalid)
              << file_faces_words(input.source, map.quality.folded_face_indices)
              << ". What to do: " << advice_words(map.advice) << "\n";
    if (!options.keep_invalid) {
      std::cerr << "meromorph: nothing was written (--keep-invalid writes the map anyway)\n";
      return int(ExitCode::cannot_parameterize);
    }
  }

  nlohmann::json report = parameterization_json(map);
  report["input"] = source_json(input.source);
  report["repairs"] = input.repairs;
  report["timings_ms"]["read"] = input.read_ms;
  report["version"] = MEROMORPH_VERSION;
  report["peak_memory_mb"] = own_peak_memory_mb(); // (until here: the writing comes after)
  add_written_vertices(map, mesh);
  outputs.writing([&] {
    write_surface(mesh, map, surface_format, output_file);
    if (!options.sphere.empty()) write_layered_sphere(mesh, map, sphere_file);
    if (!options.report.empty()) write_text_file(report_file, json_text(report) + "\n");
    outputs.commit();
  });

  const double total_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!options.quiet) std::cout << summary_line(options.input, map, total_ms) << "\n";
  return int(map.valid ? ExitCode::done : ExitCode::cannot_parameterize);
}

} // namespace

Command add_param_command(CLI::App &app) {
  auto options = std::make_shared<ParamOptions>();
  CLI::App *param = app.add_subcommand(
      "param", "Map a closed surface conformally onto the sphere: texture coordinates, branch "
               "points, layers, and a report.");
  param->add_option("INPUT", options->input, "mesh file (.ply, .obj, .off, .stl)")->required();
  param
      ->add_option("-o,--output", options->output,
                   "the surface with per-vertex (texture_u, texture_v) and per-wedge texture "
                   "coordinates, and the layer of each vertex as its quality (.ply recommended)")
      ->required();
  param->add_option("--sphere", options->sphere,
                    "the layered sphere: same vertices and faces on the sphere, with per-vertex "
                    "'layer' and 'branch' (local degree at branch points) properties (.ply)");
  param->add_option("--report", options->report, "JSON report");
  param->add_option("--uv", options->uv, "spherical (longitude, latitude) or stereographic")
      ->check(CLI::IsMember({"spherical", "stereographic"}))
      ->capture_default_str();
  param->add_flag("--no-mobius", options->no_mobius,
                  "keep the map as computed instead of centring it by a Moebius transformation");
  param
      ->add_option("--origin", options->origin,
                   "genus 1: the vertex where the map has its double pole (z = 0); default: the "
                   "first vertex whose corners are all acute")
      ->capture_default_str();
  param
      ->add_option("--forms", options->forms,
                   "genus >= 2: indices i,j of the normalized holomorphic forms in "
                   "(psi_i + psi_j) / (psi_i - psi_j); -1,-1 (default): a generic pair mixing "
                   "all forms")
      ->delimiter(',')
      ->capture_default_str();
  param
      ->add_option("--layer-gap", options->layer_gap,
                   "place layer k on the sphere of radius 1 + G*k so the layers can be seen")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  param->add_flag("--area-correct", options->area_correct,
                  "after centring, apply the Moebius transformation that makes the map most even "
                  "in area (the texture density spreads more evenly; angles are unchanged)");
  param->add_option("--pole-face", options->pole_face,
                    "genus 0: the face mapped around the north pole (default: the best-shaped face "
                    "of about median area)");
  param->add_option("--solver", options->solver, "cholmod (default) or ldlt")
      ->check(CLI::IsMember({"cholmod", "ldlt"}));
  param->add_flag("--repair", options->repair, "apply the safe repairs first (see info --help)");
  param->add_flag(
      "--strict", options->strict,
      "refuse, naming the problem, what is otherwise dealt with for the computation: "
      "holes (closed), non-manifold vertices and edges (taken apart), seam duplicate "
      "vertices (welded), doubled faces, faces that use a vertex twice and vertices "
      "on no face (left out); by default the outputs keep them all; and where the input's faces "
      "cannot carry a map without turning some over, it refuses instead of adding vertices. With "
      "--close-holes or --split-nonmanifold, all but that");
  param->add_flag("--close-holes", options->close_holes,
                  "close every hole for the computation only (the default, and with --strict; the "
                  "outputs keep the "
                  "input's faces, the holes show as gaps on the sphere)");
  param->add_flag(
      "--split-nonmanifold", options->split_nonmanifold,
      "take non-manifold vertices and edges apart for the computation (the default, and "
      "with --strict; "
      "the surface keeps its vertices, with texture coordinates per face corner; the "
      "layered sphere gets the split vertices)");
  param->add_flag("--pack-uv", options->pack_uv,
                  "several parts: each part's texture in its own cell of the unit square (a grid, "
                  "row by row from the bottom left) instead of each filling it");
  param->add_flag("--no-added-vertices", options->no_added_vertices,
                  "where the input's faces cannot carry the map without turning some over, refuse "
                  "(exit 3) instead of adding the vertices it needs to the written surface (by "
                  "default they are added after the input's, and listed in the report)");
  param->add_flag("--without-uv", options->without_uv,
                  "write the surface even in a format that cannot hold texture coordinates (.stl)");
  param->add_flag("--keep-invalid", options->keep_invalid,
                  "write the map even when it is not a valid branched cover (the exit code is "
                  "still 3)");
  param->add_flag("--quiet", options->quiet, "no progress bar and no summary line");
  return [options] { return run_param(*options); };
}

} // namespace meromorph::cli
