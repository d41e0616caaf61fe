// `meromorph match SOURCE TARGET -o OUT.ply [--landmarks PAIRS.txt] [--report R.json]
// [--both REVERSE.ply]`: every vertex of SOURCE on a point of TARGET, through their spheres.
#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/exit_codes.h"
#include "commands.h"
#include "common/errors.h"
#include "io/mesh_writer.h"
#include "io/staged_outputs.h"
#include "job_input.h"
#include "landmarks_file.h"
#include "match/surface_match.h"
#include "mesh/mesh.h"
#include "report/match_summary.h"
#include "report/report_json.h"
#include "terminal_progress.h"

namespace meromorph::cli {
namespace {

struct MatchCommandOptions {
  std::string source, target, output, landmarks, report, both;
  bool quiet = false;
};

// SOURCE's triangles on the matched points, with the target's triangle and weights per vertex.
void write_matched_mesh(const Mesh &source, const MatchedPoints &points, const std::string &file) {
  Mesh matched;
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(matched, const_cast<Mesh &>(source));
  WriteOptions options;
  VertexProperty face{"target_face", {}, false};
  FloatVertexProperty b1{"target_b1", {}}, b2{"target_b2", {}};
  for (size_t v = 0; v < matched.vert.size(); ++v) {
    if (points.target_face[v] >= 0)
      for (int k = 0; k < 3; ++k)
        matched.vert[v].P()[k] = points.position[v][k];
    face.values.push_back(points.target_face[v]);
    b1.values.push_back(float(points.weights[v][0]));
    b2.values.push_back(float(points.weights[v][1]));
  }
  options.vertex_properties = {face};
  options.float_vertex_properties = {b1, b2};
  save_mesh(matched, MeshFormat::ply, file, options);
}

std::string modulus_words(std::complex<double> tau) {
  std::ostringstream words;
  words << tau.real() << (tau.imag() < 0 ? " - " : " + ") << std::abs(tau.imag()) << "i";
  return words.str();
}

int run_match(const MatchCommandOptions &options) {
  std::vector<std::string> inputs{options.source, options.target};
  if (!options.landmarks.empty()) inputs.push_back(options.landmarks);
  StagedOutputs outputs(inputs);
  for (const std::string &path : {options.output, options.both})
    if (!path.empty() && output_format(path) != MeshFormat::ply)
      throw ArgumentError(path + ": a match is written as PLY (.ply), whose vertices can carry "
                                 "target_face, target_b1 and target_b2");
  const std::string output_file = outputs.add(options.output);
  const std::string both_file = options.both.empty() ? "" : outputs.add(options.both);
  const std::string report_file = options.report.empty() ? "" : outputs.add(options.report);
  MatchOptions settings;
  if (!options.landmarks.empty()) settings.landmarks = read_landmarks(options.landmarks);
  settings.both = !options.both.empty();

  const auto start = std::chrono::steady_clock::now();
  Mesh source, target;
  const JobInput source_input = read_job_input(options.source, false, source);
  const JobInput target_input = read_job_input(options.target, false, target);
  TerminalProgress bar(options.quiet);
  const SurfaceMatch match = match_surfaces(source, target, settings, bar.progress());
  bar.finish();

  nlohmann::json report = match_json(match, settings.landmarks.size());
  report["source"] = source_json(source_input.source);
  report["target"] = source_json(target_input.source);
  report["timings_ms"]["read"] = source_input.read_ms + target_input.read_ms;
  report["version"] = MEROMORPH_VERSION;
  outputs.writing([&] {
    write_matched_mesh(source, match.forward, output_file);
    if (settings.both) write_matched_mesh(target, match.backward, both_file);
    if (!options.report.empty()) write_text_file(report_file, json_text(report) + "\n");
    outputs.commit();
  });
  const double total_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!options.quiet) {
    std::cout << options.source << " -> " << options.target << ": genus " << match.genus << ", "
              << match_method(match);
    if (match.genus == 1)
      std::cout << " (moduli " << modulus_words(match.source_modulus) << " and "
                << modulus_words(match.target_modulus) << ", dilatation " << match.torus.dilatation
                << ")";
    std::cout << "; " << match_summary(match, settings.landmarks.size());
    if (settings.both) std::cout << "; round trip within " << 100 * match.round_trip_mean << "%";
    std::cout << " (" << total_ms / 1000 << " s)\n";
  }
  return int(ExitCode::done);
}

} // namespace

Command add_match_command(CLI::App &app) {
  auto options = std::make_shared<MatchCommandOptions>();
  CLI::App *match = app.add_subcommand(
      "match", "Every vertex of SOURCE on a point of TARGET, through their conformal spheres "
               "or flat tori (closed surfaces of genus 0, 1 or 2): OUT.ply is SOURCE's mesh on the "
               "matched points, with "
               "per-vertex target_face, target_b1 and target_b2.");
  match->add_option("SOURCE", options->source, "mesh file (.ply, .obj, .off, .stl)")->required();
  match->add_option("TARGET", options->target, "mesh file (.ply, .obj, .off, .stl)")->required();
  match->add_option("-o,--output", options->output, "the matched mesh (.ply)")->required();
  match->add_option(
      "--landmarks", options->landmarks,
      "text file of pairs \"i j\": SOURCE vertex i corresponds to TARGET vertex j "
      "(genus 0: three or more; genus 1 and 2: one or more; default: aligned automatically)");
  match->add_option("--report", options->report, "write the JSON report here");
  match->add_option("--both", options->both,
                    "also match TARGET onto SOURCE, write it here (.ply) and report the round "
                    "trip");
  match->add_flag("--quiet", options->quiet, "no progress bar and no summary line");
  return [options] { return run_match(*options); };
}

} // namespace meromorph::cli
