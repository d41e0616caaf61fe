// `meromorph info INPUT [--json] [--repair]`: what the mesh is and whether it can be mapped.
#include <iostream>

#include "cli/exit_codes.h"
#include "cli/remedy_words.h"
#include "commands.h"
#include "common/errors.h"
#include "io/mesh_reader.h"
#include "job/surface_map.h"
#include "job_input.h"
#include "mesh/repair.h"
#include "mesh/topology.h"
#include "mesh/validation.h"
#include "report/report_json.h"

namespace meromorph::cli {
namespace {

struct InfoOptions {
  std::string input;
  bool json = false;
  bool repair = false;
  bool strict = false;
};

// A finding with the remedies the grouping's heading does not already name (what param maps as
// it is can still be removed; what it refuses has only its remedies).
// Faces are named as the file numbers them too (file_faces_words, job_input.h).
std::string finding_words(const Finding &finding, bool strict, const MeshSource &source) {
  const FindingHandling handling = finding_handling(finding, strict);
  const std::string message = finding.message + file_faces_words(source, finding.faces);
  if (handling == FindingHandling::as_it_is || handling == FindingHandling::refused)
    return with_remedies(message, finding.remedies);
  return message;
}

void print_text(const MeshSource &source, const Topology &topology, const Validation &validation,
                const std::vector<std::string> &repairs, bool strict) {
  std::cout << source.path << " (" << format_name(source.format) << ")\n";
  for (const std::string &note : source.notes)
    std::cout << "  note: " << note << "\n";
  for (const std::string &repair : repairs)
    std::cout << "  repaired: " << repair << "\n";
  std::cout << "  vertices        " << topology.vertices << "\n"
            << "  edges           " << topology.edges << "\n"
            << "  faces           " << topology.faces << "\n"
            << "  components      " << topology.component_faces.size() << "\n"
            << "  boundary loops  " << topology.boundary_loops.size() << "\n"
            << "  euler char.     " << topology.euler << "\n"
            << "  genus           "
            << (topology.genus ? std::to_string(*topology.genus) : std::string("undefined"))
            << "\n";
  for (const std::string &note : validation.notes)
    std::cout << "  note: " << note << "\n";
  if (validation.ok()) {
    std::cout << "  ready: a closed, connected, oriented 2-manifold of genus "
              << (topology.genus ? *topology.genus : -1) << "\n";
    return;
  }
  // Grouped by what `param` does with them.
  const std::pair<FindingHandling, const char *> groups[] = {
      {FindingHandling::as_it_is, "meromorph param maps it as it is:"},
      {FindingHandling::close_holes,
       "meromorph param closes these for the computation (--strict refuses them):"},
      {FindingHandling::split_nonmanifold,
       "meromorph param takes these apart for the computation (--strict refuses them):"},
      {FindingHandling::set_aside,
       "meromorph param welds or leaves out these for the computation, the outputs keep them "
       "(--strict refuses them):"},
      {FindingHandling::repair, "safe repairs fix these: run again with --repair:"},
      {FindingHandling::refused, "cannot be parameterized as it is:"}};
  for (const auto &[handling, heading] : groups) {
    std::string listed;
    for (const Finding &f : validation.findings)
      if (finding_handling(f, strict) == handling)
        listed += "  - " + finding_words(f, strict, source) + "\n";
    if (!listed.empty()) std::cout << "  " << heading << "\n" << listed;
  }
}

const char *handling_name(FindingHandling handling) {
  switch (handling) {
  case FindingHandling::as_it_is:
    return "as it is";
  case FindingHandling::close_holes:
    return "closes the holes";
  case FindingHandling::split_nonmanifold:
    return "takes them apart";
  case FindingHandling::set_aside:
    return "welds or leaves them out";
  case FindingHandling::repair:
    return "--repair";
  default:
    return "refused";
  }
}

// Whether `param` with no options refuses the mesh for this finding.
bool refused_by_default(const Finding &finding, bool strict) {
  const FindingHandling handling = finding_handling(finding, strict);
  return handling == FindingHandling::repair || handling == FindingHandling::refused;
}

// The first finding that `param` with no options refuses, if any.
const Finding *refused_as_it_is(const Validation &validation, bool strict) {
  for (const Finding &f : validation.findings)
    if (refused_by_default(f, strict)) return &f;
  return nullptr;
}

int run_info(const InfoOptions &options);

// Why param (with --strict or not) refuses the mesh before computing anything; "" when it does not.
std::string what_preparation_refuses(Mesh &mesh, bool strict) {
  ParameterizeOptions settings;
  if (strict) refuse_instead(settings);
  settings.prepare_only = true;
  try {
    parameterize_surface(mesh, settings);
  } catch (const InputError &error) {
    return with_remedies(error.what(), error.remedies());
  }
  return "";
}

// `info --json` always prints JSON: a file that cannot be read gives the error in it.
int run_info_catching(const InfoOptions &options) {
  if (!options.json) return run_info(options);
  try {
    return run_info(options);
  } catch (const Error &error) {
    const nlohmann::json report = {{"input", {{"path", options.input}}},
                                   {"error",
                                    {{"exit_code", int(exit_code(error.kind()))},
                                     {"message", error.what()},
                                     {"remedies", remedies_json(error.remedies())}}},
                                   {"ok", false},
                                   {"version", MEROMORPH_VERSION}};
    std::cout << json_text(report) << "\n";
    throw;
  }
}

int run_info(const InfoOptions &options) {
  Mesh mesh;
  MeshSource source = read_mesh(options.input, mesh);
  Validation validation = validate_mesh(mesh);
  std::vector<std::string> repairs;
  Validation before_repair;
  if (options.repair && !validation.ok()) {
    before_repair = validation;
    repairs = repair_mesh(mesh);
    validation = validate_mesh(mesh);
    if (!repairs.empty()) source.triangle_face.clear(); // renumbered
  }
  const Topology topology = compute_topology(mesh);
  // What no finding tells: param's own preparation (the parts, the holes closed, the zero-area
  // faces taken out), run up to the map, refuses what param would.
  std::string preparation_refuses;
  if (!validation.ok() && !refused_as_it_is(validation, options.strict))
    preparation_refuses = what_preparation_refuses(mesh, options.strict);

  if (options.json) {
    nlohmann::json findings = findings_json(validation);
    for (size_t k = 0; k < validation.findings.size(); ++k)
      findings[k]["param"] =
          handling_name(finding_handling(validation.findings[k], options.strict));
    nlohmann::json report = {
        {"input", source_json(source)},
        {"topology", topology_json(topology)},
        {"findings", findings},
        {"param_maps_it_as_it_is",
         !refused_as_it_is(validation, options.strict) && preparation_refuses.empty()},
        {"repairs", repairs},
        {"notes", validation.notes},
        {"ok", validation.ok()},
        {"version", MEROMORPH_VERSION}};
    if (!repairs.empty()) report["findings_before_repair"] = findings_json(before_repair);
    if (!preparation_refuses.empty()) report["param_refuses"] = preparation_refuses;
    std::cout << json_text(report) << "\n";
  } else {
    print_text(source, topology, validation, repairs, options.strict);
    if (!preparation_refuses.empty())
      std::cout << "  cannot be parameterized as it is:\n  - " << preparation_refuses << "\n";
  }
  if (!preparation_refuses.empty()) {
    std::cerr << "meromorph: " << options.input
              << " cannot be parameterized as it is: " << preparation_refuses << "\n";
    return int(ExitCode::cannot_parameterize);
  }
  // What param maps, as it is or dealing with it for the computation, is no reason to fail.
  if (const Finding *first = refused_as_it_is(validation, options.strict)) {
    // The first that no repair fixes, as validation.h's main finding.
    const Finding *main_finding = first;
    size_t others = 0;
    for (const Finding &f : validation.findings) {
      if (!refused_by_default(f, options.strict)) continue;
      if (!f.repairable && main_finding->repairable) main_finding = &f;
      ++others;
    }
    --others;
    std::cerr << "meromorph: " << options.input << " cannot be parameterized as it is: "
              << finding_words(*main_finding, options.strict, source)
              << (finding_handling(*main_finding, options.strict) == FindingHandling::refused
                      ? std::string()
                      : std::string(" (meromorph param maps it with ") +
                            handling_name(finding_handling(*main_finding, options.strict)) + ")")
              << (others ? " (and " + std::to_string(others) +
                               (others == 1 ? " more problem" : " more problems") +
                               "; the full list is on standard output)"
                         : std::string())
              << "\n";
    return int(ExitCode::cannot_parameterize);
  }
  return int(ExitCode::done);
}

} // namespace

Command add_info_command(CLI::App &app) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App *info = app.add_subcommand(
      "info", "Print vertices, edges, faces, components, boundary loops, genus and every problem "
              "found, grouped by what meromorph param does with it: maps the mesh as it is "
              "(several parts, zero-area faces), deals with it for the computation (closes holes, "
              "takes non-manifold spots apart, welds seam duplicates, leaves doubled faces and "
              "vertices on no face out; --strict refuses these), maps it after --repair, or "
              "cannot. Exit code 3 unless param with its defaults maps it (JSON: "
              "param_maps_it_as_it_is, and per finding `param`).");
  info->add_option("INPUT", options->input, "mesh file (.ply, .obj, .off, .stl)")->required();
  info->add_flag("--json", options->json, "print a JSON report instead of text");
  info->add_flag("--strict", options->strict,
                 "judge the mesh as meromorph param --strict would (refusing what it otherwise "
                 "deals with for the computation)");
  info->add_flag("--repair", options->repair,
                 "apply the safe repairs (merge duplicate vertices along the edges of holes, drop "
                 "faces that use a vertex twice and unreferenced vertices, orient faces "
                 "consistently) before judging the mesh");
  return [options] { return run_info_catching(*options); };
}

} // namespace meromorph::cli
