// `meromorph forms INPUT [--report R.json] [--solver cholmod|ldlt] [--repair] [--quiet]`:
// holomorphic 1-forms, periods, modulus or Riemann matrix.
#include <chrono>
#include <fstream>
#include <iostream>

#include "cli/exit_codes.h"
#include "commands.h"
#include "common/errors.h"
#include "forms/holomorphic_pipeline.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"
#include "io/staged_outputs.h"
#include "job_input.h"
#include "mesh/repair.h"
#include "report/report_json.h"
#include "terminal_progress.h"

namespace meromorph::cli {
namespace {

struct FormsOptions {
  std::string input;
  std::string report;
  std::string solver = "cholmod";
  bool repair = false;
  bool quiet = false;
};

int run_forms(const FormsOptions &options) {
  StagedOutputs outputs({options.input});
  const std::string report_file = options.report.empty() ? "" : outputs.add(options.report);
  const SolverKind solver = solver_from_name(options.solver);
  Mesh mesh;
  const JobInput input = read_job_input(options.input, options.repair, mesh);

  TerminalProgress bar(options.quiet);
  const HolomorphicForms forms = naming_the_input(
      input.source, [&] { return compute_holomorphic_forms(mesh, solver, bar.progress()); });
  bar.finish();

  nlohmann::json report = holomorphic_forms_json(forms, solver);
  report["input"] = source_json(input.source);
  report["repairs"] = input.repairs;
  report["timings_ms"]["read"] = input.read_ms;
  report["version"] = MEROMORPH_VERSION;

  if (!options.report.empty())
    outputs.writing([&] {
      write_text_file(report_file, json_text(report) + "\n");
      outputs.commit();
    });
  // Standard output carries the JSON alone when no report file is named: the summary line then
  // goes to standard error.
  if (!options.quiet) {
    std::ostream &summary = options.report.empty() ? std::cerr : std::cout;
    summary << "genus " << forms.genus;
    if (forms.modulus)
      summary << ", modulus " << forms.modulus->real()
              << (forms.modulus->imag() < 0 ? " - " : " + ") << std::abs(forms.modulus->imag())
              << "i";
    if (forms.genus >= 2) summary << ", Riemann matrix (see the report)";
    summary << ", non-holomorphicity " << forms.non_holomorphicity_mean << "\n";
  }
  if (options.report.empty()) std::cout << json_text(report) << "\n";
  return int(ExitCode::done);
}

} // namespace

Command add_forms_command(CLI::App &app) {
  auto options = std::make_shared<FormsOptions>();
  CLI::App *forms = app.add_subcommand(
      "forms", "Holomorphic 1-forms of a closed surface: periods, the modulus (genus 1) or the "
               "Riemann matrix (genus >= 2), with residuals and timings.");
  forms->add_option("INPUT", options->input, "mesh file (.ply, .obj, .off, .stl)")->required();
  forms->add_option("--report", options->report,
                    "write the JSON report here (else to standard output, the summary line then to "
                    "standard error)");
  forms->add_option("--solver", options->solver, "cholmod (default) or ldlt")
      ->check(CLI::IsMember({"cholmod", "ldlt"}));
  forms->add_flag("--repair", options->repair, "apply the safe repairs first (see info --help)");
  forms->add_flag("--quiet", options->quiet, "no progress bar and no summary line");
  return [options] { return run_forms(*options); };
}

} // namespace meromorph::cli
