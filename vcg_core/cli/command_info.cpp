// `meromorph info INPUT [--json] [--repair]`: what the mesh is and whether it can be mapped.
#include <iostream>

#include "commands.h"
#include "errors.h"
#include "mesh_reader.h"
#include "repair.h"
#include "report_json.h"
#include "topology.h"
#include "validation.h"

namespace meromorph::cli {
namespace {

struct InfoOptions {
  std::string input;
  bool json = false;
  bool repair = false;
};

void print_text(const MeshSource &source, const Topology &topology, const Validation &validation,
                const std::vector<std::string> &repairs) {
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
  } else {
    std::cout << "  cannot be parameterized as it is:\n" << describe_findings(validation);
  }
}

int run_info(const InfoOptions &options);

// `info --json` always prints JSON: a file that cannot be read gives the error in it.
int run_info_catching(const InfoOptions &options) {
  if (!options.json) return run_info(options);
  try {
    return run_info(options);
  } catch (const Error &error) {
    const nlohmann::json report = {
        {"input", {{"path", options.input}}},
        {"error", {{"exit_code", int(error.code())}, {"message", error.what()}}},
        {"ok", false},
        {"version", MEROMORPH_VERSION}};
    std::cout << json_text(report) << "\n";
    throw;
  }
}

int run_info(const InfoOptions &options) {
  Mesh mesh;
  const MeshSource source = read_mesh(options.input, mesh);
  Validation validation = validate_mesh(mesh);
  std::vector<std::string> repairs;
  Validation before_repair;
  if (options.repair && !validation.ok()) {
    before_repair = validation;
    repairs = repair_mesh(mesh);
    validation = validate_mesh(mesh);
  }
  const Topology topology = compute_topology(mesh);

  if (options.json) {
    nlohmann::json report = {{"input", source_json(source)},
                             {"topology", topology_json(topology)},
                             {"findings", findings_json(validation)},
                             {"repairs", repairs},
                             {"notes", validation.notes},
                             {"ok", validation.ok()},
                             {"version", MEROMORPH_VERSION}};
    if (!repairs.empty()) report["findings_before_repair"] = findings_json(before_repair);
    std::cout << json_text(report) << "\n";
  } else {
    print_text(source, topology, validation, repairs);
  }
  if (!validation.ok()) {
    const Finding *main_finding = &validation.main_finding();
    const size_t others = validation.findings.size() - 1;
    std::cerr << "meromorph: " << options.input
              << " cannot be parameterized: " << main_finding->message
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
              "that keeps the mesh from being parameterized. Exit code 3 if there is one.");
  info->add_option("INPUT", options->input, "mesh file (.ply, .obj, .off, .stl)")->required();
  info->add_flag("--json", options->json, "print a JSON report instead of text");
  info->add_flag("--repair", options->repair,
                 "apply the safe repairs (merge duplicate vertices along the edges of holes, drop "
                 "faces that use a vertex twice and unreferenced vertices, orient faces "
                 "consistently) before judging the mesh");
  return [options] { return run_info_catching(*options); };
}

} // namespace meromorph::cli
