// `meromorph transfer SOURCE TARGET -o OUT.ply [--landmarks PAIRS.txt] [--report R.json]
// [--quiet]`: TARGET's per-vertex values (a PLY file's colours, texture coordinates, quality,
// labels: every scalar vertex property) carried onto SOURCE's vertices through the match
// (match/surface_match.h, match/carried_values.h). OUT.ply is SOURCE's mesh with SOURCE's own
// per-vertex values and TARGET's (TARGET's win where the names are the same).
#include <chrono>
#include <iostream>

#include "cli/exit_codes.h"
#include "commands.h"
#include "common/errors.h"
#include "io/mesh_writer.h"
#include "io/staged_outputs.h"
#include "job_input.h"
#include "landmarks_file.h"
#include "match/carried_values.h"
#include "match/surface_match.h"
#include "mesh/mesh_from_arrays.h"
#include "report/match_summary.h"
#include "report/report_json.h"
#include "terminal_progress.h"

namespace meromorph::cli {
namespace {

struct TransferCommandOptions {
  std::string source, target, output, landmarks, report;
  bool quiet = false;
};

// The values as PLY properties: one-byte integers as uchar, other integers as int, reals as
// float.
void add_properties(const std::vector<VertexValues> &values, WriteOptions &options) {
  for (const VertexValues &value : values) {
    if (value.integer) {
      VertexProperty property{value.name, {}, value.byte};
      for (double x : value.values)
        property.values.push_back(int(x));
      options.vertex_properties.push_back(std::move(property));
    } else {
      FloatVertexProperty property{value.name, {}};
      for (double x : value.values)
        property.values.push_back(float(x));
      options.float_vertex_properties.push_back(std::move(property));
    }
  }
}

int run_transfer(const TransferCommandOptions &options) {
  std::vector<std::string> inputs{options.source, options.target};
  if (!options.landmarks.empty()) inputs.push_back(options.landmarks);
  StagedOutputs outputs(inputs);
  if (output_format(options.output) != MeshFormat::ply)
    throw ArgumentError(options.output + ": a transfer is written as PLY (.ply), whose vertices "
                                         "can carry the values");
  const std::string output_file = outputs.add(options.output);
  const std::string report_file = options.report.empty() ? "" : outputs.add(options.report);
  MatchOptions settings;
  if (!options.landmarks.empty()) settings.landmarks = read_landmarks(options.landmarks);

  const auto start = std::chrono::steady_clock::now();
  Mesh source, target;
  const JobInput source_input = read_job_input(options.source, false, source, true);
  const JobInput target_input = read_job_input(options.target, false, target, true);
  const std::vector<VertexValues> &values = target_input.source.vertex_values;
  if (values.empty())
    throw InputError(options.target + ": no per-vertex values to carry: transfer reads a PLY "
                                      "file's vertex properties besides x, y, z (colours red, "
                                      "green, blue; texture_u, texture_v; quality; labels)");
  TerminalProgress bar(options.quiet);
  const SurfaceMatch match = match_surfaces(source, target, settings, bar.progress());
  bar.finish();
  const std::vector<VertexValues> carried =
      carried_values(values, arrays_from_mesh(target).triangles, match.forward);

  // SOURCE's own values that TARGET does not replace, then TARGET's.
  std::vector<VertexValues> written;
  for (const VertexValues &own : source_input.source.vertex_values)
    if (std::none_of(carried.begin(), carried.end(),
                     [&](const VertexValues &v) { return v.name == own.name; }))
      written.push_back(own);
  written.insert(written.end(), carried.begin(), carried.end());
  WriteOptions write_options;
  add_properties(written, write_options);

  nlohmann::json report = match_json(match, settings.landmarks.size());
  report["source"] = source_json(source_input.source);
  report["target"] = source_json(target_input.source);
  report["carried"] = nlohmann::json::array();
  for (const VertexValues &value : carried)
    report["carried"].push_back(value.name);
  report["timings_ms"]["read"] = source_input.read_ms + target_input.read_ms;
  report["version"] = MEROMORPH_VERSION;
  outputs.writing([&] {
    save_mesh(source, MeshFormat::ply, output_file, write_options);
    if (!options.report.empty()) write_text_file(report_file, json_text(report) + "\n");
    outputs.commit();
  });
  if (!options.quiet) {
    std::string names;
    for (const VertexValues &value : carried)
      names += (names.empty() ? "" : ", ") + value.name;
    std::cout << options.target << " -> " << options.source << ": carried " << names << " (genus "
              << match.genus << ", " << match_method(match) << "; "
              << match_summary(match, settings.landmarks.size());
    if (match.unmatched_vertices > 0) std::cout << "; the vertices not matched get 0";
    std::cout << ") ("
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
              << " s)\n";
  }
  return int(ExitCode::done);
}

} // namespace

Command add_transfer_command(CLI::App &app) {
  auto options = std::make_shared<TransferCommandOptions>();
  CLI::App *transfer = app.add_subcommand(
      "transfer", "TARGET's per-vertex values (a PLY file's colours, texture coordinates, quality, "
                  "labels) carried onto SOURCE's vertices at corresponding points, through their "
                  "conformal spheres or flat tori (closed surfaces of genus 0, 1 or 2): OUT.ply is "
                  "SOURCE's mesh with them.");
  transfer->add_option("SOURCE", options->source, "the mesh that receives (.ply, .obj, .off, .stl)")
      ->required();
  transfer->add_option("TARGET", options->target, "the mesh whose values are read (.ply)")
      ->required();
  transfer->add_option("-o,--output", options->output, "SOURCE with the values (.ply)")->required();
  transfer->add_option(
      "--landmarks", options->landmarks,
      "text file of pairs \"i j\": SOURCE vertex i corresponds to TARGET vertex "
      "j (genus 0: three or more; genus 1 and 2: one or more; default: automatic)");
  transfer->add_option("--report", options->report, "write the JSON report here");
  transfer->add_flag("--quiet", options->quiet, "no progress bar and no summary line");
  return [options] { return run_transfer(*options); };
}

} // namespace meromorph::cli
