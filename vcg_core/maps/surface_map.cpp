#include "maps/surface_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "common/errors.h"
#include "common/wording.h"
#include "maps/zero_area_images.h"
#include "mesh/mesh_from_arrays.h"
#include "mesh/nonmanifold_split.h"
#include "mesh/surface_parts.h"
#include "mesh/unit_scale.h"
#include "mesh/validation.h"
#include "mesh/zero_area_faces.h"
#include "sphere/map_quality.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {
namespace {

// The finding to tell the user first among those that splitting into parts and closing holes
// cannot deal with (one repair cannot fix, as Validation::main_finding), or nullptr.
const Finding *finding_left(const Validation &validation, bool close_holes) {
  const Finding *left = nullptr;
  for (const Finding &finding : validation.findings) {
    const FindingHandling handling = finding_handling(finding);
    if (handling == FindingHandling::as_it_is ||
        (close_holes && handling == FindingHandling::close_holes))
      continue;
    if (!finding.repairable) return &finding;
    if (!left) left = &finding;
  }
  return left;
}

// Options for one part: a vertex or face of the input applies to its own part only.
ParameterizeOptions options_for_part(const ParameterizeOptions &options, const SurfaceParts &split,
                                     int part) {
  ParameterizeOptions own = options;
  own.origin_vertex = -1;
  own.puncture_face = -1;
  if (options.origin_vertex >= 0 && size_t(options.origin_vertex) < split.part_of_vertex.size() &&
      split.part_of_vertex[size_t(options.origin_vertex)] == part)
    own.origin_vertex = split.vertex_in_part[size_t(options.origin_vertex)];
  if (options.puncture_face >= 0 && size_t(options.puncture_face) < split.part_of_face.size() &&
      split.part_of_face[size_t(options.puncture_face)] == part)
    own.puncture_face = split.face_in_part[size_t(options.puncture_face)];
  return own;
}

// Several parts, or holes to close: each part mapped on its own, in `mesh`'s numbering.
Parameterization parameterize_parts(const Mesh &mesh, const Validation &validation,
                                    const ParameterizeOptions &options, const Progress &progress) {
  const SurfaceParts split = split_into_closed_parts(mesh, options.close_holes);
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
  std::vector<std::string> advice;
  int highest_layer = 0;

  for (size_t p = 0; p < part_count; ++p) {
    const SurfacePart &part = split.parts[p];
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
    // Per vertex and face, into the input's numbering.
    for (size_t v = 0; v < part.source_vertex.size(); ++v) {
      const int source = part.source_vertex[v];
      if (source < 0) continue;
      out.sphere[size_t(source)] = map.sphere[v];
      out.layered[size_t(source)] = map.layered[v];
      out.branch_flag[size_t(source)] = map.branch_flag[v];
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
    // Figures: summed, or all of them must hold.
    out.genus += map.genus;
    out.euler = p == 0 ? map.euler : out.euler + map.euler;
    out.degree += map.degree;
    out.area_over_4pi += map.area_over_4pi;
    out.ramification += map.ramification;
    out.riemann_hurwitz_ok = out.riemann_hurwitz_ok && map.riemann_hurwitz_ok;
    out.valid = out.valid && map.valid;
    for (const std::string &reason : map.invalid)
      out.invalid.push_back(name + ": " + reason);
    if (!map.advice.empty()) advice.push_back(name + ": " + map.advice);
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
    // The part's figures stay; its per-vertex arrays were copied above.
    map.sphere.clear();
    map.layered.clear();
    map.branch_flag.clear();
    map.uv = {};
    map.sheets.vertex_layer.clear();
    map.sheets.face_layer.clear();
    out.components.push_back(std::move(map));
  }
  if (part_count == 1) {
    // One part with holes closed: its genus-specific figures are the mesh's.
    const Parameterization &only = out.components.front();
    out.modulus = only.modulus;
    out.riemann_matrix = only.riemann_matrix;
    out.non_holomorphicity_mean = only.non_holomorphicity_mean;
    out.puncture_face =
        only.puncture_face >= 0 ? split.parts[0].source_face[size_t(only.puncture_face)] : -1;
    out.origin_vertex =
        only.origin_vertex >= 0 ? split.parts[0].source_vertex[size_t(only.origin_vertex)] : -1;
    out.raised_weights = only.raised_weights;
    out.form_pair = only.form_pair;
    out.form_coefficients = only.form_coefficients;
    out.pair_attempts = only.pair_attempts;
    out.origin_attempts = only.origin_attempts;
    out.sheets.coverage = only.sheets.coverage;
  } else {
    out.method = "each part on its own (components)";
    if (options.pack_uv) {
      const int cells = int(std::ceil(std::sqrt(double(part_count) - 0.5)));
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
  for (const auto &[stage, ms] : timings)
    out.timings_ms.push_back({stage, ms});
  out.advice = join_phrases(advice);

  // Distortion on the mesh's faces, as written (at unit scale: angles do not depend on it).
  Mesh unit;
  copy_at_unit_scale(mesh, unit_scale_of(mesh), unit);
  std::vector<int> branch_vertices;
  for (const BranchPoint &b : out.branch_points)
    branch_vertices.push_back(b.vertex);
  out.quality = measure_map_quality(unit, out.sphere, branch_vertices);
  return out;
}

// The zero-area faces' images oriented (zero_area_images.h), and what follows the moved
// positions: the layered sphere, the texture coordinates at the vertices and the face corners.
void orient_put_back_faces(const Mesh &whole, const ZeroAreaFix &fix,
                           const std::vector<int> &representative,
                           const ParameterizeOptions &options, Parameterization &map) {
  const size_t vertex_count = whole.vert.size();
  std::vector<char> is_copy(vertex_count), is_branch(vertex_count);
  for (size_t v = 0; v < vertex_count; ++v) {
    is_copy[v] = representative[size_t(fix.vertex_in_work[v])] != int(v);
    is_branch[v] = map.branch_flag[v] > 1;
  }
  const std::vector<Eigen::Vector3d> before = map.sphere;
  const std::vector<int> moved =
      orient_zero_area_images(whole, fix.zero_area_faces, is_copy, is_branch, map.sphere);
  if (moved.empty()) return;
  // Packed parts' texture coordinates are scaled into their cells.
  const size_t parts = std::max<size_t>(1, map.components.size());
  const double cells = options.pack_uv ? std::ceil(std::sqrt(double(parts) - 0.5)) : 1.0;
  std::vector<std::array<double, 2>> shift(vertex_count, {0.0, 0.0});
  for (int v : moved) {
    const size_t i = size_t(v);
    map.layered[i] +=
        (map.sphere[i] - before[i]) * (1.0 + options.layer_gap * map.sheets.vertex_layer[i]);
    const auto from = texture_coordinate(before[i], options.uv),
               to = texture_coordinate(map.sphere[i], options.uv);
    double du = to[0] - from[0];
    if (options.uv == UvKind::spherical) du -= std::round(du); // across the seam
    shift[i] = {du / cells, (to[1] - from[1]) / cells};
    map.uv.vertex[i][0] += shift[i][0];
    map.uv.vertex[i][1] += shift[i][1];
  }
  for (size_t f = 0; f < whole.face.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto &d = shift[size_t(index_of(whole, whole.face[f].cV(k)))];
      map.uv.wedge[f][size_t(k)][0] += d[0];
      map.uv.wedge[f][size_t(k)][1] += d[1];
    }
  map.notes.push_back(plural(moved.size(), "vertex", "vertices") +
                      " of zero-area faces moved a little on the sphere so that their images, "
                      "and those of the faces around them, are turned the right way");
}

// `map`, computed on the mesh without its zero-area faces, on `whole`'s vertices and faces: a
// merged vertex takes the values of the vertex it was merged into; a face that was collapsed or
// flipped takes its corners' texture coordinates (unwrapped across the seam) and its first
// corner's layer. Distortion stays measured on the faces computed on.
void with_zero_area_faces(const Mesh &whole, const ZeroAreaFix &fix,
                          const ParameterizeOptions &options, Parameterization &map) {
  const size_t vertex_count = whole.vert.size(), face_count = whole.face.size();
  std::vector<int> representative(map.sphere.size(), -1); // per work vertex: a whole vertex
  for (size_t v = 0; v < vertex_count; ++v)
    if (representative[size_t(fix.vertex_in_work[v])] < 0)
      representative[size_t(fix.vertex_in_work[v])] = int(v);
  auto expand = [&](auto &values, auto blank) {
    auto old = std::move(values);
    values.assign(vertex_count, blank);
    if (old.empty()) return;
    for (size_t v = 0; v < vertex_count; ++v)
      values[v] = old[size_t(fix.vertex_in_work[v])];
  };
  expand(map.sphere, Eigen::Vector3d());
  expand(map.layered, Eigen::Vector3d());
  expand(map.uv.vertex, std::array<double, 2>{});
  expand(map.sheets.vertex_layer, 0);
  if (!map.vertex_component.empty()) expand(map.vertex_component, 0);
  std::vector<int> branch_flag = std::move(map.branch_flag);
  map.branch_flag.assign(vertex_count, 0);
  for (size_t w = 0; w < representative.size(); ++w)
    if (representative[w] >= 0) map.branch_flag[size_t(representative[w])] = branch_flag[w];
  auto to_whole = [&](int &vertex) {
    if (vertex >= 0) vertex = representative[size_t(vertex)];
  };
  for (BranchPoint &b : map.branch_points)
    to_whole(b.vertex);
  for (Parameterization &part : map.components)
    for (BranchPoint &b : part.branch_points)
      to_whole(b.vertex);
  for (ClosedHoleReport &hole : map.holes_closed)
    to_whole(hole.vertex);
  to_whole(map.origin_vertex);

  auto wedge = std::move(map.uv.wedge);
  auto around_pole = std::move(map.uv.around_pole);
  auto face_layer = std::move(map.sheets.face_layer);
  map.uv.wedge.resize(face_count);
  map.uv.around_pole.assign(face_count, 0);
  map.sheets.face_layer.assign(face_count, 0);
  for (size_t f = 0; f < face_count; ++f) {
    const int in_work = fix.face_in_work[f];
    if (in_work >= 0) {
      map.uv.wedge[f] = wedge[size_t(in_work)];
      map.uv.around_pole[f] = around_pole[size_t(in_work)];
      map.sheets.face_layer[f] = face_layer[size_t(in_work)];
      continue;
    }
    const MeshFace &face = whole.face[f];
    for (int k = 0; k < 3; ++k) {
      auto uv = map.uv.vertex[size_t(index_of(whole, face.cV(k)))];
      if (options.uv == UvKind::spherical && k > 0) // beside the first corner across the seam
        uv[0] += std::round(map.uv.wedge[f][0][0] - uv[0]);
      map.uv.wedge[f][size_t(k)] = uv;
    }
    map.sheets.face_layer[f] = map.sheets.vertex_layer[size_t(index_of(whole, face.cV(0)))];
  }
  orient_put_back_faces(whole, fix, representative, options, map);
  if (map.puncture_face >= 0)
    for (size_t f = 0; f < face_count; ++f)
      if (fix.face_in_work[f] == map.puncture_face) {
        map.puncture_face = int(f);
        break;
      }
}

} // namespace

FindingHandling finding_handling(const Finding &finding) {
  switch (finding.kind) {
  case FindingKind::several_components:
  case FindingKind::zero_area_faces:
    return FindingHandling::as_it_is;
  case FindingKind::boundary_loops:
    return FindingHandling::close_holes;
  case FindingKind::non_manifold_edges:
  case FindingKind::non_manifold_vertices:
    return FindingHandling::split_nonmanifold;
  default:
    return finding.repairable ? FindingHandling::repair : FindingHandling::refused;
  }
}

Parameterization parameterize_surface(const Mesh &input, const ParameterizeOptions &options,
                                      const Progress &progress) {
  if (options.pack_uv && options.uv != UvKind::spherical)
    throw ArgumentError("--pack-uv packs spherical texture coordinates (each part's in the unit "
                        "square); stereographic ones are unbounded");
  Validation validation = validate_mesh(input);
  const std::vector<std::string> input_notes = validation.notes;
  // Non-manifold spots taken apart first: what is left is judged on the split mesh.
  const bool nonmanifold = validation.find(FindingKind::non_manifold_edges) ||
                           validation.find(FindingKind::non_manifold_vertices);
  const bool split = nonmanifold && options.split_nonmanifold;
  Mesh split_mesh;
  NonmanifoldSplit split_spots;
  if (split) {
    split_spots = split_nonmanifold(input, split_mesh);
    validation = validate_mesh(split_mesh);
  }
  const Mesh &whole = split ? split_mesh : input;
  if (const Finding *left = finding_left(validation, options.close_holes)) {
    std::string message = left->message;
    if (left->kind == FindingKind::boundary_loops)
      message +=
          std::string(nonmanifold ? " (some where non-manifold edges were taken apart)" : "") +
          "; or let meromorph close them for the computation only (--close-holes; MeshLab "
          "and Blender: Close Holes)";
    if (left->kind == FindingKind::non_manifold_edges ||
        left->kind == FindingKind::non_manifold_vertices)
      message += "; or let meromorph take them apart for the computation (--split-nonmanifold; "
                 "MeshLab and Blender: Split Non-Manifold Spots)";
    // The split mesh numbers its copies after the input's vertices: say whose they are.
    std::string copies;
    for (int v : left->vertices)
      if (split && size_t(v) >= input.vert.size())
        copies += (copies.empty() ? "" : ", ") + std::to_string(v) + " is a copy of " +
                  std::to_string(split_spots.source_vertex[size_t(v)]);
    if (!copies.empty())
      message += " (vertices from " + std::to_string(input.vert.size()) +
                 " on are copies made where non-manifold spots were split: " + copies + ")";
    throw InputError(message);
  }
  // Zero-area faces taken out of the computation (they are kept in the outputs).
  Mesh flat_free;
  ZeroAreaFix flat_fix;
  const bool flat = validation.find(FindingKind::zero_area_faces) != nullptr;
  if (flat) {
    flat_fix = take_out_zero_area_faces(whole, flat_free);
    validation = validate_mesh(flat_free);
    if (const Finding *left = finding_left(validation, options.close_holes))
      throw InputError(left->message + " (after zero-area faces were taken out)");
    if (const Finding *still = validation.find(FindingKind::zero_area_faces))
      throw InputError(still->message);
  }
  const Mesh &mesh = flat ? flat_free : whole;
  // The split copies sit on their originals by construction: of the notes, only the input's own.
  if (split)
    validation.notes.erase(std::remove_if(validation.notes.begin(), validation.notes.end(),
                                          [&](const std::string &note) {
                                            return std::count(input_notes.begin(),
                                                              input_notes.end(), note) == 0;
                                          }),
                           validation.notes.end());
  Parameterization out = validation.ok() ? parameterize(mesh, options, progress, &validation)
                                         : parameterize_parts(mesh, validation, options, progress);
  if (flat) {
    with_zero_area_faces(whole, flat_fix, options, out);
    out.notes.push_back(
        plural(flat_fix.zero_area_faces.size(), "face has", "faces have") +
        " zero area: taken out of the computation (" +
        plural(size_t(flat_fix.collapsed_edges), "edge", "edges") + " collapsed, " +
        plural(size_t(flat_fix.flipped_edges), "edge", "edges") +
        " flipped) and kept in the outputs, with their corners' texture coordinates");
  }
  if (split) {
    out.nonmanifold_split = {split_spots.split_vertices, split_spots.split_edges,
                             split_spots.added_vertices};
    out.sphere_source_vertex = split_spots.source_vertex;
    out.sphere_faces = arrays_from_mesh(whole).triangles; // the per-vertex arrays are whole's
    out.notes.push_back(
        "non-manifold spots taken apart for the computation: " +
        std::to_string(split_spots.split_vertices.size()) + " vertices split into " +
        std::to_string(split_spots.split_vertices.size() + size_t(split_spots.added_vertices)) +
        ", " + plural(split_spots.split_edges.size(), "edge", "edges") +
        " with more than two faces taken apart; the layered sphere has the split vertices, "
        "the surface keeps its own (each face corner has its texture coordinates)");
    for (BranchPoint &b : out.branch_points) {
      b.sphere_vertex = b.vertex;
      b.vertex = split_spots.source_vertex[size_t(b.vertex)];
    }
    for (ClosedHoleReport &hole : out.holes_closed)
      hole.vertex = split_spots.source_vertex[size_t(hole.vertex)];
  }
  return out;
}

void layered_sphere_mesh(const Mesh &input, const Parameterization &map, Mesh &sphere) {
  MeshArrays arrays = arrays_from_mesh(input);
  if (!map.sphere_faces.empty()) arrays.triangles = map.sphere_faces;
  arrays.positions.resize(map.layered.size());
  for (size_t v = 0; v < map.layered.size(); ++v)
    arrays.positions[v] = Point3(map.layered[v][0], map.layered[v][1], map.layered[v][2]);
  mesh_from_arrays(arrays, sphere);
}

} // namespace meromorph
