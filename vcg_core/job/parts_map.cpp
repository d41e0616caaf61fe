#include "job/parts_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "common/errors.h"
#include "common/wording.h"
#include "mesh/surface_parts.h"
#include "mesh/unit_scale.h"
#include "sphere/map_quality.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {
namespace {

// Options for one part: a vertex or face of the input applies to its own part only.
ParameterizeOptions options_for_part(const ParameterizeOptions &options, const SurfaceParts &split,
                                     int part) {
  ParameterizeOptions own = options;
  own.origin_vertex = -1;
  own.pole_face = -1;
  if (options.origin_vertex >= 0 && size_t(options.origin_vertex) < split.part_of_vertex.size() &&
      split.part_of_vertex[size_t(options.origin_vertex)] == part)
    own.origin_vertex = split.vertex_in_part[size_t(options.origin_vertex)];
  if (options.pole_face >= 0 && size_t(options.pole_face) < split.part_of_face.size() &&
      split.part_of_face[size_t(options.pole_face)] == part)
    own.pole_face = split.face_in_part[size_t(options.pole_face)];
  return own;
}

// The part's map in the mesh's numbering: per vertex and face, its branch points, and the gap
// each of its closed holes leaves on the sphere.
void place_part(const SurfaceParts &split, size_t p, Parameterization &map, Parameterization &out,
                int &highest_layer) {
  const SurfacePart &part = split.parts[p];
  // Per vertex and face, into the input's numbering.
  for (size_t v = 0; v < part.source_vertex.size(); ++v) {
    const int source = part.source_vertex[v];
    if (source < 0) continue;
    out.sphere[size_t(source)] = map.sphere[v];
    out.layered[size_t(source)] = map.layered[v];
    out.branch_flag[size_t(source)] = map.branch_flag[v];
    if (!map.flat.empty()) {
      if (out.flat.empty()) out.flat.assign(out.sphere.size(), Complex(0, 0));
      out.flat[size_t(source)] = map.flat[v];
    }
    out.uv.vertex[size_t(source)] = map.uv.vertex[v];
    out.sheets.vertex_layer[size_t(source)] = map.sheets.vertex_layer[v];
    highest_layer = std::max(highest_layer, map.sheets.vertex_layer[v]);
  }
  for (size_t f = 0; f < part.source_face.size(); ++f) {
    const int source = part.source_face[f];
    if (source < 0) continue;
    out.uv.wedge[size_t(source)] = map.uv.wedge[f];
    out.uv.around_pole[size_t(source)] = map.uv.around_pole[f];
    out.sheets.face_layer[size_t(source)] = map.sheets.face_layer[f];
  }
  for (BranchPoint &b : map.branch_points) {
    b.vertex = part.source_vertex[size_t(b.vertex)];
    if (b.vertex >= 0) out.branch_points.push_back(b);
  }
  for (const ClosedHole &hole : split.holes)
    if (hole.part == int(p)) {
      double area = 0;
      for (int f : hole.faces) {
        const MeshFace &face = part.mesh.face[size_t(f)];
        area += signed_solid_angle(map.sphere[size_t(index_of(part.mesh, face.cV(0)))],
                                   map.sphere[size_t(index_of(part.mesh, face.cV(1)))],
                                   map.sphere[size_t(index_of(part.mesh, face.cV(2)))]);
      }
      out.holes_closed.push_back({int(p), hole.edges, hole.vertex, area / (4 * M_PI)});
    }
}

// The part's figures into the whole's: summed, or all of them must hold.
void add_part_figures(const std::string &name, size_t p, const Parameterization &map,
                      Parameterization &out, std::map<std::string, double> &timings) {
  out.genus += map.genus;
  out.euler = p == 0 ? map.euler : out.euler + map.euler;
  out.degree += map.degree;
  out.area_over_4pi += map.area_over_4pi;
  out.ramification += map.ramification;
  out.riemann_hurwitz_ok = out.riemann_hurwitz_ok && map.riemann_hurwitz_ok;
  out.valid = out.valid && map.valid;
  for (const std::string &reason : map.invalid)
    out.invalid.push_back(name + ": " + reason);
  for (const Advice &advice : map.advice)
    out.advice.push_back({name + ": " + advice.cause, advice.remedy});
  out.sheets.count = std::max(out.sheets.count, map.sheets.count);
  out.sheets.cut_faces += map.sheets.cut_faces;
  out.snapped_branch_points += map.snapped_branch_points;
  out.untangled_vertices += map.untangled_vertices;
  for (const auto &[stage, ms] : map.timings_ms)
    timings[stage] += ms;
  if (p == 0) {
    out.method = map.method;
    out.mobius = map.mobius;
  }
}

// After all parts: one part's genus-specific figures are the mesh's; several parts get their
// texture cells (with `pack_uv`) and their layered spheres side by side along x.
void finish_parts(const SurfaceParts &split, const ParameterizeOptions &options, int highest_layer,
                  Parameterization &out) {
  const size_t part_count = split.parts.size();
  const size_t vertex_count = out.sphere.size(), face_count = out.uv.wedge.size();
  if (part_count == 1) {
    // One part with holes closed: its genus-specific figures are the mesh's.
    const Parameterization &only = out.components.front();
    out.modulus = only.modulus;
    out.riemann_matrix = only.riemann_matrix;
    out.non_holomorphicity_mean = only.non_holomorphicity_mean;
    out.pole_face = only.pole_face >= 0 ? split.parts[0].source_face[size_t(only.pole_face)] : -1;
    out.origin_vertex =
        only.origin_vertex >= 0 ? split.parts[0].source_vertex[size_t(only.origin_vertex)] : -1;
    out.raised_weights = only.raised_weights;
    out.intrinsic_delaunay = only.intrinsic_delaunay;
    out.form_pair = only.form_pair;
    out.form_coefficients = only.form_coefficients;
    out.pair_attempts = only.pair_attempts;
    out.origin_attempts = only.origin_attempts;
    out.sheets.coverage = only.sheets.coverage;
    out.area_correction = only.area_correction;
  } else {
    out.method = "each part on its own (components)";
    if (options.pack_uv) {
      const int cells = texture_grid_cells(part_count);
      auto into_cell = [&](int part, std::array<double, 2> &uv) {
        uv[0] = (double(part % cells) + uv[0]) / cells;
        uv[1] = (double(part / cells) + uv[1]) / cells;
      };
      for (size_t v = 0; v < vertex_count; ++v)
        into_cell(split.part_of_vertex[v], out.uv.vertex[v]);
      for (size_t f = 0; f < face_count; ++f)
        for (auto &uv : out.uv.wedge[f])
          into_cell(split.part_of_face[f], uv);
      out.notes.push_back("texture coordinates packed: part k in cell k of a " +
                          std::to_string(cells) + " x " + std::to_string(cells) +
                          " grid over the unit square, row by row from the bottom left");
    }
    // The parts' layered spheres side by side along x.
    out.component_spacing = 2.5 * (1 + options.layer_gap * highest_layer);
    out.vertex_component = split.part_of_vertex;
    for (size_t v = 0; v < vertex_count; ++v)
      out.layered[v].x() += out.component_spacing * split.part_of_vertex[v];
  }
}

} // namespace

int texture_grid_cells(size_t part_count) {
  return int(std::ceil(std::sqrt(double(part_count) - 0.5)));
}

Parameterization parameterize_parts(Mesh &mesh, const Validation &validation,
                                    const ParameterizeOptions &options, const Progress &progress) {
  SurfaceParts split = split_into_closed_parts(mesh, options.close_holes);
  const size_t part_count = split.parts.size();
  Parameterization out;
  out.notes = validation.notes;
  if (part_count > 1)
    out.notes.push_back("the mesh has " + std::to_string(part_count) +
                        " separate parts: each is mapped on its own");
  if (!split.holes.empty())
    out.notes.push_back(plural(split.holes.size(), "hole was", "holes were") +
                        " closed for the computation only; the outputs hold the input's faces");

  const size_t vertex_count = mesh.vert.size(), face_count = mesh.face.size();
  out.sphere.resize(vertex_count);
  out.layered.resize(vertex_count);
  out.branch_flag.assign(vertex_count, 0);
  out.uv.vertex.resize(vertex_count);
  out.uv.wedge.resize(face_count);
  out.uv.around_pole.assign(face_count, 0);
  out.sheets.vertex_layer.assign(vertex_count, 0);
  out.sheets.face_layer.assign(face_count, 0);
  out.riemann_hurwitz_ok = out.valid = true;
  out.mobius_applied = options.mobius;
  std::map<std::string, double> timings;
  int highest_layer = 0;

  for (size_t p = 0; p < part_count; ++p) {
    SurfacePart &part = split.parts[p];
    const std::string name = "part " + std::to_string(p + 1) + " of " + std::to_string(part_count);
    Parameterization map = [&] {
      try {
        return parameterize(
            part.mesh, options_for_part(options, split, int(p)),
            progress.range(double(p) / double(part_count), double(p + 1) / double(part_count)));
      } catch (const InputError &error) {
        throw InputError(name + " (input faces from " + std::to_string(part.source_face.front()) +
                         "): " + error.what());
      }
    }();
    place_part(split, p, map, out, highest_layer);
    add_part_figures(name, p, map, out, timings);
    // The part's figures stay; its per-vertex arrays were copied above.
    map.sphere.clear();
    map.layered.clear();
    map.branch_flag.clear();
    map.flat.clear();
    map.uv = {};
    map.sheets.vertex_layer.clear();
    map.sheets.face_layer.clear();
    out.components.push_back(std::move(map));
  }
  finish_parts(split, options, highest_layer, out);
  for (const auto &[stage, ms] : timings)
    out.timings_ms.push_back({stage, ms});

  // Distortion on the mesh's faces, as written (at unit scale: angles do not depend on it).
  const UnitScaleInPlace unit(mesh);
  std::vector<int> branch_vertices;
  for (const BranchPoint &b : out.branch_points)
    branch_vertices.push_back(b.vertex);
  out.quality = measure_map_quality(mesh, out.sphere, branch_vertices);
  return out;
}

} // namespace meromorph
