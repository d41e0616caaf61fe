#include "remesh/surface_remesh.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/append.h>

#include "common/errors.h"
#include "common/job_threads.h"
#include "mesh/unit_scale.h"
#include "remesh/flat_torus_lift.h"
#include "remesh/geodesic_sphere.h"
#include "remesh/layered_sphere_lift.h"
#include "remesh/lifted_edge_flips.h"
#include "remesh/lifted_refinement.h"
#include "remesh/lifted_relaxation.h"
#include "sphere/area_correction.h"

namespace meromorph {
namespace {

// The mesh the map is on: the input's vertices and faces, or the split mesh's.
struct MappedMesh {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::array<int, 3>> faces;
  std::vector<int> part; // per vertex
};

MappedMesh mapped_mesh(const Mesh &input, const Parameterization &map) {
  MappedMesh out;
  const size_t count = map.sphere.size();
  out.positions.resize(count);
  out.part.assign(count, 0);
  for (size_t v = 0; v < count; ++v) {
    const size_t source = map.sphere_source_vertex.empty() ? v : map.sphere_source_vertex[v];
    out.positions[v] = input.vert[source].cP().ToEigenVector<Eigen::Vector3d>();
    if (!map.vertex_component.empty())
      out.part[v] = map.vertex_component[v < map.vertex_component.size() ? v : source];
  }
  if (!map.sphere_faces.empty()) {
    out.faces = map.sphere_faces;
  } else {
    for (const auto &face : input.face)
      out.faces.push_back(
          {index_of(input, face.cV(0)), index_of(input, face.cV(1)), index_of(input, face.cV(2))});
  }
  return out;
}

// Part k of the mapped mesh as a mapped surface (path_lifting.h), with its faces' layers and its
// vertices' local degrees.
struct PartSurface {
  MappedSurface surface;
  std::vector<int> face_layer, local_degree, global_vertex;
  std::vector<Eigen::Vector3d> branch_values;
  int ramification = 0;
  // Genus 1: the flat coordinate per vertex and the lattice (flat_torus_lift.h); empty otherwise.
  std::vector<Complex> flat;
  std::array<Complex, 2> flat_periods{};
};

PartSurface part_surface(const MappedMesh &mapped, const Parameterization &map, int part) {
  PartSurface out;
  std::vector<int> local(mapped.positions.size(), -1);
  for (size_t v = 0; v < mapped.positions.size(); ++v)
    if (mapped.part[v] == part) {
      local[v] = int(out.global_vertex.size());
      out.global_vertex.push_back(int(v));
      out.surface.positions.push_back(mapped.positions[v]);
      out.surface.image.push_back(map.sphere[v]);
      const int e = v < map.branch_flag.size() ? map.branch_flag[v] : 0;
      out.local_degree.push_back(e);
      if (e >= 2) {
        out.branch_values.push_back(map.sphere[v]);
        out.ramification += e - 1;
      }
      if (!map.flat.empty()) out.flat.push_back(map.flat[v]);
    }
  const Parameterization &own = map.components.empty() ? map : map.components[size_t(part)];
  if (own.genus == 1 && out.flat.size() == out.global_vertex.size())
    out.flat_periods = own.flat_periods;
  else
    out.flat.clear();
  Mesh mesh; // for vcglib's face-face adjacency
  vcg::tri::Allocator<Mesh>::AddVertices(mesh, out.global_vertex.size());
  for (size_t f = 0; f < mapped.faces.size(); ++f) {
    const auto &c = mapped.faces[f];
    if (local[c[0]] < 0) continue;
    out.surface.faces.push_back({local[c[0]], local[c[1]], local[c[2]]});
    out.face_layer.push_back(f < map.sheets.face_layer.size() ? map.sheets.face_layer[f] : 0);
    vcg::tri::Allocator<Mesh>::AddFace(mesh, &mesh.vert[local[c[0]]], &mesh.vert[local[c[1]]],
                                       &mesh.vert[local[c[2]]]);
  }
  vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
  out.surface.across.resize(mesh.face.size());
  for (size_t f = 0; f < mesh.face.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto *other = mesh.face[f].cFFp(k);
      out.surface.across[f][k] = other == &mesh.face[f] ? -1 : index_of(mesh, other);
    }
  return out;
}

// The part's geodesic sphere of `figures.frequency`, lifted; the vertex count it holds when
// everything lifts goes into `figures`. Genus 1: as many samples on the flat torus.
LiftedSphere lift_part(const PartSurface &surface, RemeshPart &figures, const Progress &progress) {
  if (!surface.flat.empty()) {
    const long long k = figures.frequency;
    figures.target_vertices = (long long)figures.degree * (10 * k * k + 2) - figures.ramification;
    return lift_flat_torus(surface.surface, surface.flat, surface.flat_periods, surface.face_layer,
                           surface.local_degree, figures.target_vertices);
  }
  // Where the lifts of a face's sides do not close (a walk passing a branch point a rounding
  // apart), the sphere is refined there and lifted again, twice at most.
  std::vector<Eigen::Vector3d> refine_at;
  for (int attempt = 0;; ++attempt) {
    const GeodesicSphere sphere =
        geodesic_sphere(figures.frequency, surface.branch_values, refine_at);
    figures.target_vertices =
        (long long)figures.degree * (long long)sphere.vertices.size() - figures.ramification;
    LiftedSphere lifted = lift_sphere(surface.surface, surface.face_layer, surface.local_degree,
                                      figures.degree, sphere, progress);
    if (lifted.unclosed_at.empty() || attempt == 2) return lifted;
    refine_at.insert(refine_at.end(), lifted.unclosed_at.begin(), lifted.unclosed_at.end());
  }
}

double surface_area(const MappedSurface &surface) {
  double total = 0;
  for (const auto &c : surface.faces)
    total += 0.5 * (surface.positions[c[1]] - surface.positions[c[0]])
                       .cross(surface.positions[c[2]] - surface.positions[c[0]])
                       .norm();
  return total;
}

// Rounds of splitting: a face over a long limb's image (1e-8 of the sphere and less) is quartered
// each round until the surface under it fits the target: 24 rounds on the
// four-tentacle blob at 4,660 vertices, 5 on kitten.nf20k, where nothing is left to split sooner.
constexpr int refinement_rounds = 40;
constexpr double largest_face = 1.8; // times the target face area

// The refinement's limits for a target face area, `scale` times that allowed.
RefinementLimits refinement_limits(double face_area, double scale, const SampleLocator &samples) {
  RefinementLimits limits;
  limits.face_area = largest_face * scale * face_area;
  limits.samples = &samples;
  return limits;
}

// The vertices a lift at `frequency` would hold after refinement, estimated from a lift at
// `lifted_frequency`: each face there stands for (k / k0)^2 faces of 1 / (k / k0)^2 its area,
// each split 1-to-4 until at most 2.5 times the target (an estimate on the generous side).
double vertices_after_refinement(const std::vector<double> &areas, int lifted_frequency,
                                 int frequency, double face_area) {
  const double scale = double(frequency) / double(lifted_frequency);
  double faces = 0;
  for (double area : areas) {
    double pieces = scale * scale, each = area / (scale * scale);
    for (int round = 0; round < refinement_rounds && each > 2.5 * face_area; ++round) {
      pieces *= 4;
      each /= 4;
    }
    faces += pieces;
  }
  return faces / 2;
}

// The highest frequency up to the lifted one whose refined lift holds about the target.
int frequency_after_refinement(const LiftedSphere &lifted, int lifted_frequency, double face_area,
                               long long target, const SurfaceSamples &samples) {
  std::vector<double> areas = lifted_face_areas(lifted);
  const std::vector<double> covered = SampleLocator(samples).covered_areas(lifted);
  for (size_t f = 0; f < areas.size(); ++f)
    areas[f] = std::max(areas[f], covered[f]);
  int frequency = lifted_frequency;
  while (frequency > 1 && vertices_after_refinement(areas, lifted_frequency, frequency, face_area) >
                              1.03 * double(target))
    frequency = std::max(1, int(frequency * 0.97));
  return frequency;
}

void smooth_lifted_sphere(const PartSurface &surface, int rounds, LiftedSphere &lifted) {
  for (int round = 0; round < rounds; ++round) {
    flip_lifted_edges(surface.surface, 4, lifted);
    relax_lifted_sphere(surface.surface, surface.face_layer, 2, lifted);
  }
}

// Of several tries, the lift whose vertex count lands closest to a target (on a log scale).
struct ClosestTry {
  LiftedSphere best;
  double best_miss = 1e300;
  bool kept_last = false;
  // Keeps `lifted` when it is the closest so far (kept_last); returns its count over the target.
  double offer(LiftedSphere &&lifted, long long target) {
    const double held = double(lifted.positions.size()) / double(target);
    const double miss = std::abs(std::log(held));
    kept_last = miss < best_miss;
    if (kept_last) {
      best_miss = miss;
      best = std::move(lifted);
    }
    return held;
  }
};

// The lifted sphere refined so that it holds about `target` vertices: the largest face area
// allowed is scaled by how far a try lands from the target, and where the plain lift alone holds
// more than the target the sphere's frequency is lowered; the closest of a few tries is kept.
void refine_to_target(const PartSurface &surface, RemeshPart &figures, double face_area,
                      const SurfaceSamples &samples, long long target, const Progress &progress,
                      LiftedSphere &lifted) {
  // The samples located on the plain lift once; each try copies that.
  SampleLocator located(samples);
  located.covered_areas(lifted);
  ClosestTry closest;
  double scale = 1.0;
  int best_frequency = figures.frequency;
  for (int attempt = 0; attempt < 6; ++attempt) {
    LiftedSphere refined = lifted;
    refine_lifted_sphere(surface.surface, refinement_limits(face_area, scale, located),
                         refinement_rounds, refined);
    const double held = closest.offer(std::move(refined), target);
    if (closest.kept_last) best_frequency = figures.frequency;
    if (held > 0.95 && held < 1.05) break;
    scale *= std::pow(held, 1.5);
    const double lift_holds = double(lifted.positions.size()) / double(target);
    if (lift_holds > 0.9 && figures.frequency > 1) {
      figures.frequency =
          std::max(1, int(std::floor(figures.frequency / std::sqrt(lift_holds / 0.8))));
      lifted = lift_part(surface, figures, progress);
      located = SampleLocator(samples);
      located.covered_areas(lifted);
    }
  }
  lifted = std::move(closest.best);
  figures.frequency = best_frequency;
}

// Genus 1: the flat torus sampled so that, refined where the surface is large against its flat
// image, it holds about the target: the sample count and the largest face area allowed are both
// scaled by how far a try lands, the closest of a few tries kept.
LiftedSphere flat_torus_to_target(const PartSurface &surface, double face_area,
                                  const SurfaceSamples &samples, long long target) {
  ClosestTry closest;
  double grid_samples = double(target), scale = 1.0;
  for (int attempt = 0; attempt < 6; ++attempt) {
    LiftedSphere lifted =
        lift_flat_torus(surface.surface, surface.flat, surface.flat_periods, surface.face_layer,
                        surface.local_degree, std::llround(grid_samples));
    refine_lifted_sphere(surface.surface,
                         refinement_limits(face_area, scale, SampleLocator(samples)),
                         refinement_rounds, lifted);
    const double held = closest.offer(std::move(lifted), target);
    if (std::abs(std::log(held)) < 0.03) break;
    grid_samples /= std::sqrt(held);
    scale *= held;
  }
  return std::move(closest.best);
}

// A closed part whose lift has faces that do not close, or sphere faces with a corner that did not
// lift, would come out open: refused, naming the two branch values nearest each other on the
// sphere (where that has been seen to happen). A part
// with holes (closed for the map only) has gaps on the sphere, and its remesh has the holes: its
// lift is not held to closing.
void refuse_unclosed(const PartSurface &surface, const LiftedSphere &lifted, int part) {
  if (lifted.unclosed_faces == 0 && lifted.unlifted_faces == 0) return;
  for (const auto &sides : surface.surface.across)
    for (int other : sides)
      if (other < 0) return; // the part has a hole

  std::vector<int> branch_vertices;
  for (size_t v = 0; v < surface.local_degree.size(); ++v)
    if (surface.local_degree[v] >= 2) branch_vertices.push_back(int(v));
  double nearest = 1e300;
  int a = -1, b = -1;
  for (size_t i = 0; i < branch_vertices.size(); ++i)
    for (size_t j = i + 1; j < branch_vertices.size(); ++j) {
      const double d =
          (surface.surface.image[branch_vertices[i]] - surface.surface.image[branch_vertices[j]])
              .norm();
      if (d < nearest) {
        nearest = d;
        a = surface.global_vertex[branch_vertices[i]];
        b = surface.global_vertex[branch_vertices[j]];
      }
    }
  std::string where;
  if (a >= 0) {
    std::ostringstream words;
    words << "; the branch points at vertices " << a << " and " << b << " have values only "
          << std::setprecision(2) << nearest << " apart on the sphere";
    where = words.str();
  }
  std::string what;
  if (lifted.unlifted_faces > 0)
    what = std::to_string(lifted.unlifted_faces) + " sphere faces did not lift";
  if (lifted.unclosed_faces > 0)
    what += (what.empty() ? "" : " and ") + std::to_string(lifted.unclosed_faces) +
            " lifted faces do not close up";
  throw InputError("the remesh of part " + std::to_string(part) + " does not close: " + what +
                   " (nothing was written)" + where);
}

// The part's lift appended to the remesh, without the vertices on no face (a lift whose faces all
// fell in a hole's gap).
void append_part(const LiftedSphere &lifted, int part, SurfaceRemesh &out) {
  std::vector<int> index(lifted.positions.size(), -1);
  for (const auto &face : lifted.faces)
    for (int corner : face)
      index[size_t(corner)] = 0;
  int kept = int(out.mesh.vert.size());
  for (int &slot : index)
    if (slot == 0) slot = kept++;
  const int offset = int(out.mesh.vert.size());
  auto vertex = vcg::tri::Allocator<Mesh>::AddVertices(out.mesh, size_t(kept - offset));
  for (size_t v = 0; v < lifted.positions.size(); ++v) {
    if (index[v] < 0) continue;
    vertex->P() = Point3(lifted.positions[v].x(), lifted.positions[v].y(), lifted.positions[v].z());
    ++vertex;
    out.layer.push_back(lifted.layer[v]);
    out.local_degree.push_back(lifted.local_degree[v]);
    out.part.push_back(part);
    out.sphere.push_back(lifted.sphere[v]);
  }
  for (const auto &face : lifted.faces)
    vcg::tri::Allocator<Mesh>::AddFace(out.mesh, &out.mesh.vert[size_t(index[size_t(face[0])])],
                                       &out.mesh.vert[size_t(index[size_t(face[1])])],
                                       &out.mesh.vert[size_t(index[size_t(face[2])])]);
  out.unlifted_faces += lifted.unlifted_faces;
  out.unclosed_faces += lifted.unclosed_faces;
  out.folded_lifts += lifted.folded_lifts;
}

// The lifted sphere evened out to about `part_target` vertices (or the resolution's count):
// refined where faces lift large, smoothed, and what still folds split once more.
void even_out_part(const PartSurface &surface, const RemeshOptions &options, long long part_target,
                   bool flat_to_target, const Progress &step, RemeshPart &figures,
                   LiftedSphere &lifted) {
  const long long even_target = options.resolution >= 0 ? figures.target_vertices : part_target;
  const double face_area = surface_area(surface.surface) / (2.0 * double(even_target));
  // Samples of a quarter of the target face area: a face over a limb's image is split until no
  // more of the surface lies under it than its target.
  const SurfaceSamples samples = sample_surface(surface.surface, face_area / 4);
  if (flat_to_target) {
    lifted = flat_torus_to_target(surface, face_area, samples, even_target);
  } else if (options.resolution < 0) {
    const int frequency =
        frequency_after_refinement(lifted, figures.frequency, face_area, even_target, samples);
    if (frequency != figures.frequency) {
      figures.frequency = frequency;
      lifted = lift_part(surface, figures, step.range(0.5, 0.9));
    }
    refine_to_target(surface, figures, face_area, samples, even_target, step.range(0.5, 0.9),
                     lifted);
  } else
    refine_lifted_sphere(surface.surface, refinement_limits(face_area, 1.0, SampleLocator(samples)),
                         refinement_rounds, lifted);
  smooth_lifted_sphere(surface, options.relaxation_rounds, lifted);
  for (int round = 0; round < 2 && lifted.folded_lifts > 0; ++round) {
    LiftedSphere split = lifted;
    RefinementLimits folded;
    folded.folded = true;
    refine_lifted_sphere(surface.surface, folded, 1, split);
    smooth_lifted_sphere(surface, options.relaxation_rounds / 2, split);
    if (split.folded_lifts >= lifted.folded_lifts) break; // it did not help
    lifted = std::move(split);
  }
  figures.target_vertices = even_target;
}

void remesh_at_target(const Mesh &given, const Parameterization &map, const RemeshOptions &options,
                      const Progress &progress, SurfaceRemesh &out) {
  if (options.resolution > 12)
    throw ArgumentError("the resolution is at most 12 (167 million sphere vertices)");
  if (options.vertices > max_remesh_vertices || (options.vertices >= 0 && options.vertices < 12))
    throw ArgumentError("the vertex target is " + std::to_string(options.vertices) +
                        "; give 12 to " + std::to_string(max_remesh_vertices));
  if (map.sphere.empty() || given.vert.empty()) throw ArgumentError("remesh: the mesh is empty");
  const JobThreads threads; // the team for this job's loops: common/job_threads.h
  // Computed at unit scale (unit_scale.h), so that a surface in nanometres or light years gives
  // the same remesh; its positions are put back at the input's scale at the end.
  const UnitScale scale = unit_scale_of(given);
  Mesh input;
  copy_at_unit_scale(given, scale, input);
  const MappedMesh mapped = mapped_mesh(input, map);
  const int parts = map.components.empty() ? 1 : int(map.components.size());
  const long long target = options.vertices > 0 ? options.vertices : (long long)input.vert.size();
  for (int part = 0; part < parts; ++part) {
    const Progress step = progress.range(0.8 * part / parts, 0.8 * (part + 1) / parts);
    const PartSurface surface = part_surface(mapped, map, part);
    RemeshPart figures;
    figures.degree = map.components.empty() ? map.degree : map.components[part].degree;
    figures.ramification = surface.ramification;
    const double vertex_share = double(surface.global_vertex.size()) / double(mapped.part.size());
    const long long part_target = std::llround(double(target) * vertex_share);
    figures.frequency =
        options.resolution >= 0
            ? 1 << options.resolution
            : frequency_for_vertices(part_target, figures.degree, figures.ramification);
    // Genus 1 evened out to a vertex target samples its flat torus to that target below.
    const bool flat_to_target = !surface.flat.empty() && options.even_out && options.resolution < 0;
    LiftedSphere lifted;
    if (!flat_to_target) lifted = lift_part(surface, figures, step.range(0.0, 0.5));
    if (options.even_out)
      even_out_part(surface, options, part_target, flat_to_target, step, figures, lifted);
    join_near_boundary_vertices(surface.surface, lifted);
    if (lifted.folded_lifts > 0) drop_folded_boundary_faces(surface.surface, lifted);
    refuse_unclosed(surface, lifted, part);
    out.target_vertices += figures.target_vertices;
    append_part(lifted, part, out);
    out.parts.push_back(figures);
  }
  progress.report(0.8, "remesh quality");
  out.quality = measure_remesh(input, out.mesh, out.local_degree);
  // A closed surface remeshes to a closed surface of its genus, or not at all.
  if (map.holes_closed.empty() && map.sphere_faces.empty() &&
      (out.quality.euler != map.euler || out.quality.boundary_edges > 0))
    throw InputError("the remesh came out with Euler characteristic " +
                         std::to_string(out.quality.euler) + " and " +
                         std::to_string(out.quality.boundary_edges) +
                         " boundary edges, not the surface's " + std::to_string(map.euler) +
                         " and none (the map crowds too much of the surface into a spot)",
                     {Remedy::remesh});
  for (MeshVertex &vertex : out.mesh.vert)
    vertex.P() = scale.undo(vertex.cP());
  // Evening out fills the regions the sphere samples sparsely; without it they are reported.
  if (!options.even_out && parts == 1 && map.sphere_faces.empty())
    out.sparse_regions = sparsely_sampled_regions(
        input, sample_shares(input, map.sphere, map.degree), options.sparse_below, 0.005);
  progress.report(1.0, "done");
}

double mesh_area(const Mesh &mesh) {
  double total = 0;
  for (const MeshFace &face : mesh.face)
    total += vcg::DoubleArea(face) / 2;
  return total;
}

// The fewest vertices found whose remesh lies within `options.max_error` of the surface both ways:
// the chordal distance falls about as one over the vertex count, so each try's target is the last
// one scaled by its distance over the bound (10% beyond it when short, and at most 8 times); the
// smallest try that meets the bound is kept.
void remesh_to_max_error(const Mesh &given, const Parameterization &map,
                         const RemeshOptions &options, const Progress &progress,
                         SurfaceRemesh &out) {
  RemeshOptions attempt = options;
  attempt.max_error = -1;
  if (attempt.vertices <= 0)
    attempt.vertices = std::max<long long>(12, (long long)given.vert.size());
  double closest = 1e300;
  long long closest_vertices = 0;
  bool met = false;
  for (int k = 0; k < options.max_error_tries; ++k) {
    SurfaceRemesh remesh;
    remesh_at_target(given, map, attempt,
                     progress.range(double(k) / options.max_error_tries,
                                    double(k + 1) / options.max_error_tries),
                     remesh);
    const double error =
        std::max(remesh.quality.hausdorff_to_input, remesh.quality.hausdorff_from_input);
    const long long held = (long long)remesh.mesh.vert.size();
    if (error <= options.max_error && (!met || held < (long long)out.mesh.vert.size())) {
      vcg::tri::Append<Mesh, Mesh>::MeshCopy(out.mesh, remesh.mesh);
      out.layer = std::move(remesh.layer);
      out.local_degree = std::move(remesh.local_degree);
      out.part = std::move(remesh.part);
      out.sphere = std::move(remesh.sphere);
      out.parts = std::move(remesh.parts);
      out.target_vertices = remesh.target_vertices;
      out.unlifted_faces = remesh.unlifted_faces;
      out.unclosed_faces = remesh.unclosed_faces;
      out.folded_lifts = remesh.folded_lifts;
      out.quality = remesh.quality;
      out.sparse_regions = std::move(remesh.sparse_regions);
      met = true;
    }
    if (!met && error < closest) {
      closest = error;
      closest_vertices = held;
    }
    // Within 15% under the bound: close enough to the fewest.
    if (error <= options.max_error && error > 0.85 * options.max_error) break;
    const double scale =
        std::clamp(error / options.max_error * (error > options.max_error ? 1.1 : 1.0), 0.25, 8.0);
    const long long next = std::clamp<long long>(std::llround(double(attempt.vertices) * scale), 12,
                                                 max_remesh_vertices);
    if (next == attempt.vertices) break;
    attempt.vertices = next;
  }
  if (!met) {
    std::ostringstream words;
    words << "no remesh within " << 100 * options.max_error
          << "% of the diagonal was found; the closest, with " << closest_vertices
          << " vertices, is " << 100 * closest
          << "% away (give a larger --max-error, or --vertices)";
    throw InputError(words.str());
  }
}

} // namespace

void remesh_through_sphere(const Mesh &given, const Parameterization &map,
                           const RemeshOptions &options, const Progress &progress,
                           SurfaceRemesh &out) {
  const int targets = (options.vertices > 0) + (options.resolution >= 0) +
                      (options.edge_length > 0) + (options.max_error > 0);
  if (targets > 1)
    throw ArgumentError("give one of the resolution, the vertex count, the edge length and the "
                        "largest error");
  if (options.edge_length > 0 && !(options.edge_length < 1e300))
    throw ArgumentError("the edge length must be a positive number");
  if (options.max_error > 0) {
    if (!(options.max_error < 1))
      throw ArgumentError("the largest error is a fraction of the diagonal below 1");
    remesh_to_max_error(given, map, options, progress, out);
    return;
  }
  RemeshOptions at_target = options;
  if (options.edge_length > 0) {
    // Equilateral triangles of that side, two per vertex, tile the surface.
    const double vertices =
        mesh_area(given) / (std::sqrt(3.0) / 2 * options.edge_length * options.edge_length);
    if (!(vertices <= double(max_remesh_vertices)))
      throw ArgumentError("an edge length of " + std::to_string(options.edge_length) +
                          " needs more than " + std::to_string(max_remesh_vertices) +
                          " vertices on this surface");
    at_target.vertices = std::max<long long>(12, std::llround(vertices));
  }
  remesh_at_target(given, map, at_target, progress, out);
}

} // namespace meromorph
