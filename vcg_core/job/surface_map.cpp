#include "job/surface_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "common/errors.h"
#include "common/job_threads.h"
#include "common/wording.h"
#include "job/carry_back.h"
#include "job/parts_map.h"
#include "job/set_aside.h"
#include "job/zero_area_put_back.h"
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

// Findings about single vertices and faces, which taking non-manifold spots apart leaves as they
// are.
bool split_leaves_it(FindingKind kind) {
  return kind == FindingKind::empty_mesh || kind == FindingKind::non_finite_coordinates ||
         kind == FindingKind::repeated_vertex_in_face ||
         kind == FindingKind::unreferenced_vertices || kind == FindingKind::beyond_double_precision;
}

// What param cannot take, as the refusal says it: the finding (with its remedies: the option
// that would take it), and which of the vertices named are copies the split made (it numbers them
// after the input's).
[[noreturn]] void refuse(const Finding &left, bool nonmanifold, bool split, const Mesh &input,
                         const NonmanifoldSplit &split_spots) {
  std::string more;
  if (left.kind == FindingKind::boundary_loops && nonmanifold)
    more += " (some where non-manifold edges were taken apart)";
  std::string copies;
  for (int v : left.vertices)
    if (split && size_t(v) >= input.vert.size())
      copies += (copies.empty() ? "" : ", ") + std::to_string(v) + " is a copy of " +
                std::to_string(split_spots.source_vertex[size_t(v)]);
  if (!copies.empty())
    more += " (vertices from " + std::to_string(input.vert.size()) +
            " on are copies made where non-manifold spots were split: " + copies + ")";
  throw refusal(left, more);
}

// The map of the split mesh said in the input's terms: what was split, the sphere's faces and
// each sphere vertex's source, branch points and holes at input vertices.
void report_split(const Mesh &whole, const NonmanifoldSplit &split_spots, Parameterization &out) {
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

} // namespace

FindingHandling finding_handling(const Finding &finding, bool strict) {
  if (strict) {
    const FindingHandling handling = finding_handling(finding);
    if (handling == FindingHandling::as_it_is || handling == FindingHandling::repair)
      return handling;
    return finding.repairable ? FindingHandling::repair : FindingHandling::refused;
  }
  switch (finding.kind) {
  case FindingKind::several_components:
  case FindingKind::zero_area_faces:
    return FindingHandling::as_it_is;
  case FindingKind::boundary_loops:
    return FindingHandling::close_holes;
  case FindingKind::non_manifold_edges:
  case FindingKind::non_manifold_vertices:
    return FindingHandling::split_nonmanifold;
  case FindingKind::duplicate_vertices:
  case FindingKind::repeated_vertex_in_face:
  case FindingKind::duplicate_faces:
  case FindingKind::unreferenced_vertices:
    return FindingHandling::set_aside;
  default:
    return finding.repairable ? FindingHandling::repair : FindingHandling::refused;
  }
}

namespace {

// A refusal about a mesh derived from the input (other face numbers): its faces not passed on.
InputError in_other_numbers(const InputError &error) {
  return InputError(error.what(), error.remedies());
}

Parameterization parameterize_surface_here(Mesh &input, const ParameterizeOptions &options,
                                           const Progress &progress);

// The map computed with seam duplicates welded, and doubled faces, faces that use a vertex twice
// and vertices on no face left out (set_aside.h), carried back to every input vertex and face.
Parameterization parameterize_without_defects(const Mesh &input, const Validation &validation,
                                              const ParameterizeOptions &options,
                                              const Progress &progress) {
  SetAside aside;
  set_aside_defects(input, validation, aside);
  ParameterizeOptions work_options = options; // the chosen vertex and face in the work's numbers
  work_options.set_aside_defects = work_options.add_vertices = false;
  if (options.origin_vertex >= 0 && size_t(options.origin_vertex) < aside.vertex_in_work.size())
    work_options.origin_vertex = aside.vertex_in_work[size_t(options.origin_vertex)];
  if (options.pole_face >= 0 && size_t(options.pole_face) < aside.face_in_work.size())
    work_options.pole_face = aside.face_in_work[size_t(options.pole_face)];
  if ((options.origin_vertex >= 0 && work_options.origin_vertex < 0) ||
      (options.pole_face >= 0 && work_options.pole_face < 0))
    throw ArgumentError("the chosen origin vertex or pole face is left out of the computation (" +
                        join_phrases(aside.notes) + ")");
  Parameterization out;
  try {
    out = parameterize_surface_here(aside.work, work_options, progress);
  } catch (const InputError &error) {
    throw in_other_numbers(InputError(std::string(error.what()) +
                                          " (vertex and face numbers after " +
                                          join_phrases(aside.notes) + ")",
                                      error.remedies()));
  }
  if (options.prepare_only) return out;
  carry_back(input, aside.work.vert.size(), aside.vertex_in_work, aside.face_in_work, options, out);
  out.notes.insert(out.notes.begin(), aside.notes.begin(), aside.notes.end());
  return out;
}

Parameterization parameterize_surface_here(Mesh &input, const ParameterizeOptions &options,
                                           const Progress &progress) {
  progress.report(0.0, "checking the mesh");
  if (options.pack_uv && options.uv_kind != UvKind::spherical)
    throw ArgumentError("packing the parts' texture coordinates (each part's in its own cell of "
                        "the unit square) needs spherical ones; stereographic ones are unbounded",
                        {Remedy::choose_uv_kind});
  Validation validation = validate_mesh(input);
  if (options.set_aside_defects && has_defects_to_set_aside(validation))
    return parameterize_without_defects(input, validation, options, progress);
  const std::vector<std::string> input_notes = validation.notes;
  // Non-manifold spots taken apart first: what is left is judged on the split mesh.
  const bool nonmanifold = validation.find(FindingKind::non_manifold_edges) ||
                           validation.find(FindingKind::non_manifold_vertices);
  const bool split = nonmanifold && options.split_nonmanifold;
  Mesh split_mesh;
  NonmanifoldSplit split_spots;
  if (split) {
    // What taking the spots apart cannot change is refused first: the split costs far more.
    Validation unaffected = validation;
    unaffected.findings.erase(
        std::remove_if(unaffected.findings.begin(), unaffected.findings.end(),
                       [](const Finding &finding) { return !split_leaves_it(finding.kind); }),
        unaffected.findings.end());
    if (const Finding *left = finding_left(unaffected, options.close_holes))
      refuse(*left, nonmanifold, false, input, split_spots);
    split_spots = split_nonmanifold(input, split_mesh);
    validation = validate_mesh(split_mesh);
  }
  Mesh &whole = split ? split_mesh : input;
  if (const Finding *left = finding_left(validation, options.close_holes))
    refuse(*left, nonmanifold, split, input, split_spots);
  // Zero-area faces taken out of the computation (they are kept in the outputs).
  Mesh flat_free;
  ZeroAreaFix flat_fix;
  const bool flat = validation.find(FindingKind::zero_area_faces) != nullptr;
  if (flat) {
    flat_fix = take_out_zero_area_faces(whole, flat_free);
    validation = validate_mesh(flat_free);
    if (const Finding *left = finding_left(validation, options.close_holes))
      throw in_other_numbers(refusal(*left, " (after zero-area faces were taken out)"));
    // Left after the take-out: only a change of the model removes them.
    if (const Finding *still = validation.find(FindingKind::zero_area_faces)) {
      Finding left = *still;
      left.remedies = {Remedy::remesh};
      throw in_other_numbers(refusal(left, " (left after meromorph took out those it could)"));
    }
  }
  Mesh &mesh = flat ? flat_free : whole;
  // The split copies sit on their originals by construction: of the notes, only the input's own.
  if (split)
    validation.notes.erase(std::remove_if(validation.notes.begin(), validation.notes.end(),
                                          [&](const std::string &note) {
                                            return std::count(input_notes.begin(),
                                                              input_notes.end(), note) == 0;
                                          }),
                           validation.notes.end());
  if (options.prepare_only) { // every refusal about the mesh's structure made, nothing computed
    if (!validation.ok()) split_into_closed_parts(mesh, options.close_holes);
    return {};
  }
  // Vertices are added only where the mesh computed on is the one written.
  ParameterizeOptions work_options = options;
  work_options.add_vertices = options.add_vertices && validation.ok() && !split && !flat;
  Parameterization out = validation.ok()
                             ? parameterize(mesh, work_options, progress, &validation)
                             : parameterize_parts(mesh, validation, work_options, progress);
  if (flat) {
    with_zero_area_faces(whole, flat_fix, options, out);
    out.notes.push_back(
        plural(flat_fix.zero_area_faces.size(), "face has", "faces have") +
        " zero area: taken out of the computation (" +
        plural(size_t(flat_fix.collapsed_edges), "edge", "edges") + " collapsed, " +
        plural(size_t(flat_fix.flipped_edges), "edge", "edges") +
        " flipped) and kept in the outputs, with their corners' texture coordinates");
  }
  if (split) report_split(whole, split_spots, out);
  return out;
}

} // namespace

Parameterization parameterize_surface(Mesh &input, const ParameterizeOptions &options,
                                      const Progress &progress) {
  // The job runs on a worker thread; the callback is called on this one, steadily.
  Parameterization out;
  run_reporting(progress, [&](const Progress &relay) {
    const JobThreads threads; // the team for this job's loops: common/job_threads.h
    out = parameterize_surface_here(input, options, relay);
  });
  return out;
}

Parameterization parameterize_arrays(const VertexPositions &V, const TriangleCorners &F,
                                     const ParameterizeOptions &options, const Progress &progress) {
  MeshArrays arrays;
  arrays.positions.reserve(size_t(V.rows()));
  for (Eigen::Index v = 0; v < V.rows(); ++v)
    arrays.positions.emplace_back(V(v, 0), V(v, 1), V(v, 2));
  arrays.triangles.reserve(size_t(F.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    arrays.triangles.push_back({F(f, 0), F(f, 1), F(f, 2)});
  Mesh mesh;
  mesh_from_arrays(arrays, mesh);
  return parameterize_surface(mesh, options, progress);
}

void add_written_vertices(const Parameterization &map, Mesh &input) {
  if (map.added_vertices.empty()) return;
  MeshArrays arrays = arrays_from_mesh(input);
  for (const AddedVertex &added : map.added_vertices)
    arrays.positions.emplace_back(added.position[0], added.position[1], added.position[2]);
  arrays.triangles = map.surface_faces;
  mesh_from_arrays(arrays, input);
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
