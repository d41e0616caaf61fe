// JSON views of the core's results, shared by the CLI reports and the C ABI.
//
// In:  a Topology, a Validation, a MeshSource, a Parameterization, a SurfaceRemesh,
//      HolomorphicForms, a SurfaceMatch.
// Out: nlohmann::json objects with the field names documented in the README (`info --json`), and
//      their text.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "forms/holomorphic_pipeline.h"
#include "io/mesh_reader.h"
#include "maps/parameterization.h"
#include "match/surface_match.h"
#include "mesh/topology.h"
#include "mesh/validation.h"
#include "remesh/surface_remesh.h"

namespace meromorph {

nlohmann::json topology_json(const Topology &topology);
// ["close_holes", ...]: remedy codes (common/remedy.h) by name.
nlohmann::json remedies_json(const std::vector<Remedy> &remedies);
nlohmann::json findings_json(const Validation &validation);
nlohmann::json source_json(const MeshSource &source);

// The REPORT.json of `meromorph param` (design.md section 3), without input, repairs and version.
nlohmann::json parameterization_json(const Parameterization &map);

// The `remesh` part of the REPORT.json of `meromorph remesh`, and the area correction's figures.
nlohmann::json remesh_json(const SurfaceRemesh &remesh);
nlohmann::json area_correction_json(const AreaCorrection &correction);

// The report of `meromorph forms` without input, repairs, read time and version: genus, periods,
// the modulus (genus 1) or the Riemann matrix (genus >= 2) with the canonical (symplectic) basis
// of homology it is taken in, residuals and timings.
nlohmann::json holomorphic_forms_json(const HolomorphicForms &forms, SolverKind solver);

// The report of `meromorph match` without inputs, read time and version: genus, method, the
// alignment (genus 0: its cost and the other rotations that fit; genus 1: the lattice map, shift,
// dilatation and alternatives; genus 2: its cost, how far the branch values land from the
// target's, the alternatives' costs), landmark residuals, the matched mesh's angle error and folds,
// the moduli (genus 1), the round trip (when matched both ways) and timings. `match_method`: the
// words of the method.
nlohmann::json match_json(const SurfaceMatch &match, size_t landmark_count);
const std::string &match_method(const SurfaceMatch &match);

// The text of a report, indented by 2. Bytes that are not UTF-8 (a file name, or file content
// quoted in a message) are replaced by U+FFFD rather than failing.
std::string json_text(const nlohmann::json &report);

// [[re, im], ...] rows of a complex matrix.
nlohmann::json complex_matrix_json(const Eigen::MatrixXcd &matrix);

} // namespace meromorph
