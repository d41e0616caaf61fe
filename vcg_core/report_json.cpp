#include "report_json.h"

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

nlohmann::json findings_json(const Validation &validation) {
  nlohmann::json findings = nlohmann::json::array();
  for (const Finding &f : validation.findings) {
    nlohmann::json edges = nlohmann::json::array();
    for (const auto &edge : f.edges)
      edges.push_back({edge[0], edge[1]});
    findings.push_back({{"code", finding_code(f.kind)},
                        {"message", f.message},
                        {"repairable", f.repairable},
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

} // namespace meromorph
