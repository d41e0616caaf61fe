// `meromorph remesh INPUT -o OUT [--resolution N | --vertices K | --edge-length L |
// --max-error E | --like TEMPLATE [--landmarks PAIRS.txt]] [--report R.json] ...`: a new
// triangulation of the surface sampled through its layered sphere (surface_remesh.h), or the
// template's triangulation put on it through the match (surface_match.h).
#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cli/exit_codes.h"
#include "cli/remedy_words.h"
#include "commands.h"
#include "common/errors.h"
#include "common/wording.h"
#include "io/mesh_writer.h"
#include "io/staged_outputs.h"
#include "job/surface_map.h"
#include "job_input.h"
#include "landmarks_file.h"
#include "match/surface_match.h"
#include "remesh/surface_remesh.h"
#include "report/remesh_summary.h"
#include "report/report_json.h"
#include "terminal_progress.h"

namespace meromorph::cli {
namespace {

struct RemeshCommandOptions {
  std::string input, output, report, like, landmarks;
  int resolution = -1;
  long long vertices = -1;
  double edge_length = -1, max_error_percent = -1;
  bool no_area_correct = false, uniform = false, repair = false, close_holes = false,
       split_nonmanifold = false, quiet = false;
};

// OUT: the remeshed surface; as PLY with per-vertex layer, branch (local degree), part and the
// sphere position (sphere_x, sphere_y, sphere_z).
void write_remesh(const SurfaceRemesh &remesh, MeshFormat format, const std::string &file) {
  WriteOptions options;
  if (format == MeshFormat::ply) {
    options.vertex_properties = {{"layer", remesh.layer, false},
                                 {"branch", remesh.local_degree, true},
                                 {"part", remesh.part, false}};
    for (int axis = 0; axis < 3; ++axis) {
      FloatVertexProperty coordinate{std::string("sphere_") + char('x' + axis), {}};
      for (const Eigen::Vector3d &p : remesh.sphere)
        coordinate.values.push_back(float(p[axis]));
      options.float_vertex_properties.push_back(coordinate);
    }
  }
  save_mesh(remesh.mesh, format, file, options);
}

void warn_sparse_regions(const SurfaceRemesh &remesh) {
  for (const SparseRegion &region : remesh.sparse_regions)
    std::cerr << "meromorph: warning: a region of " << region.faces << " faces ("
              << std::setprecision(3) << 100 * region.area_share << "% of the surface, near vertex "
              << region.vertex << ") gets only " << 100 * region.sample_share
              << "% of its fair share of samples: its triangles are larger there\n";
}

// --like TEMPLATE: the template's triangles on INPUT, its vertex i at the point of INPUT that
// corresponds to it through their conformal spheres or flat tori (match/surface_match.h): a
// collection remeshed like one template has one connectivity, vertex i at corresponding points.
int remesh_like(const RemeshCommandOptions &options, StagedOutputs &outputs, MeshFormat format,
                const std::string &output_file, const std::string &report_file) {
  MatchOptions settings;
  if (!options.landmarks.empty()) settings.landmarks = read_landmarks(options.landmarks);
  Mesh input, like;
  const JobInput input_read = read_job_input(options.input, true, input);
  const JobInput like_read = read_job_input(options.like, false, like);
  TerminalProgress bar(options.quiet);
  const SurfaceMatch match = match_surfaces(like, input, settings, bar.progress());
  bar.finish();
  if (match.unmatched_vertices > 0)
    throw InputError(options.input + ": " + std::to_string(match.unmatched_vertices) + " of " +
                     std::to_string(like.vert.size()) + " vertices of " + options.like +
                     " found no corresponding point on it");
  Mesh remeshed;
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(remeshed, like);
  for (size_t v = 0; v < remeshed.vert.size(); ++v)
    for (int k = 0; k < 3; ++k)
      remeshed.vert[v].P()[k] = match.forward.position[v][k];
  nlohmann::json report = {{"input", source_json(input_read.source)},
                           {"repairs", input_read.repairs},
                           {"like", source_json(like_read.source)},
                           {"match", match_json(match, settings.landmarks.size())},
                           {"version", MEROMORPH_VERSION}};
  outputs.writing([&] {
    save_mesh(remeshed, format, output_file);
    if (!report_file.empty()) write_text_file(report_file, json_text(report) + "\n");
    outputs.commit();
  });
  if (!options.quiet)
    std::cout << options.input << " remeshed like " << options.like << ": " << remeshed.vert.size()
              << " vertices, " << remeshed.face.size() << " faces, genus " << match.genus << " ("
              << match_method(match) << "); the remesh's angles differ from the template's by "
              << match.angle_error_mean_degrees << " deg on average, " << match.folded_faces
              << " folded faces\n";
  return int(ExitCode::done);
}

int run_remesh(const RemeshCommandOptions &options) {
  std::vector<std::string> inputs{options.input};
  for (const std::string &path : {options.like, options.landmarks})
    if (!path.empty()) inputs.push_back(path);
  StagedOutputs outputs(inputs);
  const MeshFormat remesh_format = output_format(options.output);
  const std::string output_file = outputs.add(options.output);
  const std::string report_file = options.report.empty() ? "" : outputs.add(options.report);
  if (!options.landmarks.empty() && options.like.empty())
    throw ArgumentError("--landmarks pairs a template's vertices with the input's: give --like");
  if (!options.like.empty()) {
    if ((options.resolution >= 0) || (options.vertices > 0) || (options.edge_length > 0) ||
        (options.max_error_percent > 0) || options.uniform)
      throw ArgumentError("--like gives the remesh the template's vertices and triangles: no "
                          "size option (--resolution, --vertices, --edge-length, --max-error, "
                          "--semi-regular) goes with it");
    return remesh_like(options, outputs, remesh_format, output_file, report_file);
  }
  if ((options.resolution >= 0) + (options.vertices > 0) + (options.edge_length > 0) +
          (options.max_error_percent > 0) >
      1)
    throw ArgumentError(
        "--resolution, --vertices, --edge-length and --max-error each set the remesh's size: "
        "give one");

  ParameterizeOptions settings;
  settings.area_correct = !options.no_area_correct;
  settings.close_holes = options.close_holes;
  settings.split_nonmanifold = options.split_nonmanifold;
  settings.set_aside_defects = false; // the remesh samples the input's own faces
  RemeshOptions remesh_options;
  remesh_options.resolution = options.resolution;
  remesh_options.vertices = options.vertices;
  remesh_options.edge_length = options.edge_length;
  remesh_options.max_error = options.max_error_percent > 0 ? options.max_error_percent / 100 : -1;
  remesh_options.even_out = !options.uniform;

  Mesh mesh;
  // The remesh is a new triangulation, so the safe repairs (seam duplicates welded, doubled
  // faces and vertices on no face removed) always come first: nothing needs to attach to the
  // input's vertices.
  const JobInput input = read_job_input(options.input, true, mesh);
  TerminalProgress bar(options.quiet);
  const Parameterization map = naming_the_input(input.source, [&] {
    return parameterize_surface(mesh, settings, bar.progress().range(0.0, 0.6));
  });
  if (!map.valid) {
    bar.finish();
    std::cerr << "meromorph: error: " << options.input
              << ": no valid map on this triangulation, so nothing to remesh through: "
              << join_phrases(map.invalid) << ". What to do: " << advice_words(map.advice) << "\n";
    return int(ExitCode::cannot_parameterize);
  }
  SurfaceRemesh remesh;
  add_written_vertices(map, mesh); // the surface the map was written on
  remesh_through_sphere(mesh, map, remesh_options, bar.progress().range(0.6, 1.0), remesh);
  bar.finish();

  nlohmann::json report = parameterization_json(map);
  report["input"] = source_json(input.source);
  report["repairs"] = input.repairs;
  report["remesh"] = remesh_json(remesh);
  report["version"] = MEROMORPH_VERSION;
  outputs.writing([&] {
    write_remesh(remesh, remesh_format, output_file);
    if (!options.report.empty()) write_text_file(report_file, json_text(report) + "\n");
    outputs.commit();
  });
  if (!options.quiet) {
    warn_sparse_regions(remesh);
    std::cout << remesh_summary(options.input, map, remesh) << "\n";
  }
  return int(ExitCode::done);
}

} // namespace

Command add_remesh_command(CLI::App &app) {
  auto options = std::make_shared<RemeshCommandOptions>();
  CLI::App *remesh = app.add_subcommand(
      "remesh", "A new triangulation of the surface, sampled through its layered sphere: "
                "semi-regular, with vertices where the map branches, for any genus.");
  remesh->add_option("INPUT", options->input, "mesh file (.ply, .obj, .off, .stl)")->required();
  remesh
      ->add_option("-o,--output", options->output,
                   "the remeshed surface; as .ply with per-vertex 'layer', 'branch' (local degree "
                   "at branch vertices), 'part' and the sphere position sphere_x, sphere_y, "
                   "sphere_z")
      ->required();
  remesh->add_option("--report", options->report,
                     "JSON report: the map's and the remesh's figures");
  remesh
      ->add_option("--resolution", options->resolution,
                   "sample the icosphere of N subdivisions (10 * 4^N + 2 vertices per layer)")
      ->check(CLI::Range(0, 12));
  remesh
      ->add_option("--vertices", options->vertices,
                   "about this many vertices in the result (default: as many as the input)")
      ->check(CLI::Range(12LL, max_remesh_vertices));
  remesh
      ->add_option("--edge-length", options->edge_length,
                   "about this edge length, in the input's units (the vertex count of equilateral "
                   "triangles of that side tiling the surface)")
      ->check(CLI::PositiveNumber);
  remesh
      ->add_option("--max-error", options->max_error_percent,
                   "the remesh within this distance of the surface both ways (Hausdorff, in "
                   "percent of the bounding-box diagonal), with as few vertices as the tries find")
      ->check(CLI::Range(1e-6, 50.0));
  remesh->add_flag("--no-area-correct", options->no_area_correct,
                   "sample the map as centred, without the Moebius area correction (long parts "
                   "then get fewer samples)");
  remesh->add_flag("--semi-regular,--uniform", options->uniform,
                   "keep the subdivided sphere's triangles as they lift, without splitting those "
                   "over much of the surface (subdivision connectivity, for wavelets and "
                   "multiresolution; long parts get few vertices)");
  remesh->add_flag("--repair", options->repair,
                   "the safe repairs (see info --help): always made before a remesh; accepted "
                   "for scripts that give it");
  remesh->add_flag("--close-holes", options->close_holes,
                   "close every hole for the map only (the remesh keeps a hole there)");
  remesh->add_flag("--split-nonmanifold", options->split_nonmanifold,
                   "take non-manifold vertices and edges apart for the map");
  remesh->add_option("--like", options->like,
                     "TEMPLATE mesh (closed, the input's genus, 0, 1 or 2): the remesh gets its "
                     "triangles, its vertex i at the input's point corresponding to the "
                     "template's vertex i (a collection remeshed like one template: one "
                     "connectivity, corresponding vertices)");
  remesh->add_option("--landmarks", options->landmarks,
                     "with --like: text file of pairs \"i j\", template vertex i corresponds to "
                     "input vertex j (genus 0: three or more; default: automatic)");
  remesh->add_flag("--quiet", options->quiet, "no progress bar and no summary line");
  return [options] { return run_remesh(*options); };
}

} // namespace meromorph::cli
