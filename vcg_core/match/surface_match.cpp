#include "match/surface_match.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include <Eigen/Geometry>

#include "common/errors.h"
#include "common/parallel_for.h"
#include "forms/holomorphic_pipeline.h"
#include "job/set_aside.h"
#include "job/surface_map.h"
#include "maps/parameterization.h"
#include "match/flat_torus.h"
#include "mesh/face_vectors.h"
#include "mesh/mesh_edges.h"
#include "mesh/validation.h"
#include "sphere/sphere_triangle_grid.h"

namespace meromorph {
namespace {

// A surface as its map was written: the input's vertices then any added, its faces (pieces of
// the input's), and (genus 0) each vertex's sphere point.
struct MappedSurface {
  std::vector<Eigen::Vector3d> positions, sphere;
  std::vector<std::array<int, 3>> faces, input_faces;
  std::vector<int> face_source; // per written face, the input's face it is part of
  double diagonal = 1;
};

std::vector<Eigen::Vector3d> positions_of(const Mesh &mesh) {
  std::vector<Eigen::Vector3d> out;
  for (const auto &vertex : mesh.vert)
    out.emplace_back(vertex.cP()[0], vertex.cP()[1], vertex.cP()[2]);
  return out;
}

std::vector<std::array<int, 3>> triangles_of(const Mesh &mesh) {
  std::vector<std::array<int, 3>> out;
  for (const auto &face : mesh.face)
    out.push_back({int(index_of(mesh, face.cV(0))), int(index_of(mesh, face.cV(1))),
                   int(index_of(mesh, face.cV(2)))});
  return out;
}

double diagonal_of(const std::vector<Eigen::Vector3d> &positions) {
  Eigen::Vector3d low = positions.front(), high = low;
  for (const Eigen::Vector3d &p : positions)
    low = low.cwiseMin(p), high = high.cwiseMax(p);
  return std::max((high - low).norm(), 1e-300);
}

// V - E + F of a closed triangle mesh (each edge on two faces) is 2 - 2 genus when it is one part;
// counted on the mesh with its defects set aside (job/set_aside.h).
int closed_genus_estimate(const Mesh &mesh) {
  const Validation validation = validate_mesh(mesh);
  if (!has_defects_to_set_aside(validation))
    return (2 - (int(mesh.vert.size()) - int(mesh.face.size()) / 2)) / 2;
  SetAside aside;
  set_aside_defects(mesh, validation, aside);
  return (2 - (int(aside.work.vert.size()) - int(aside.work.face.size()) / 2)) / 2;
}

MappedSurface genus0_sphere(Mesh &mesh, const char *which, const Progress &progress) {
  const Parameterization map = parameterize_surface(mesh, ParameterizeOptions{}, progress);
  const std::string name = which;
  if (map.components.size() > 1)
    throw InputError("the " + name + " has " + std::to_string(map.components.size()) +
                     " parts: a match takes one closed surface; map its parts apart");
  if (map.genus != 0)
    throw InputError("the " + name + " has genus " + std::to_string(map.genus) +
                     ": matching covers genus 0 and 1 so far (both surfaces closed, of the same "
                     "genus)");
  if (!map.valid)
    throw InputError("no valid map of the " + name +
                     " on its triangulation: " + join_phrases(map.invalid));
  MappedSurface out;
  out.positions = positions_of(mesh);
  out.input_faces = triangles_of(mesh);
  for (const AddedVertex &added : map.added_vertices)
    out.positions.push_back(added.position);
  out.faces = map.surface_faces.empty() ? out.input_faces : map.surface_faces;
  out.face_source = map.surface_face_source;
  if (out.face_source.empty())
    for (size_t f = 0; f < out.faces.size(); ++f)
      out.face_source.push_back(int(f));
  out.sphere = map.sphere;
  out.diagonal = diagonal_of(out.positions);
  return out;
}

std::vector<double> sphere_face_areas(const MappedSurface &surface) {
  std::vector<double> out;
  for (const auto &t : surface.faces)
    out.push_back(0.5 * (surface.sphere[size_t(t[1])] - surface.sphere[size_t(t[0])])
                            .cross(surface.sphere[size_t(t[2])] - surface.sphere[size_t(t[0])])
                            .norm());
  return out;
}

// A genus-1 surface as a flat torus, on its own triangles.
struct TorusOfSurface {
  MappedSurface surface;
  FlatTorus torus;
  std::vector<int> face_corners; // 3 per face
  std::vector<double> factor;    // log conformal factor per vertex
};

// The flat torus is computed on the mesh with its defects set aside (job/set_aside.h: seam
// duplicates welded, doubled faces and vertices on no face left out) and read back on the input's
// own vertices and faces; those left out get no flat point (no match, and found by nothing).
TorusOfSurface genus1_torus(const Mesh &mesh, const char *which, const Progress &progress) {
  const std::string name = which;
  const Validation validation = validate_mesh(mesh);
  SetAside aside;
  const bool set_aside = has_defects_to_set_aside(validation);
  if (set_aside) set_aside_defects(mesh, validation, aside);
  const Mesh &work = set_aside ? aside.work : mesh;
  const HolomorphicForms forms = compute_holomorphic_forms(work, SolverKind::cholmod, progress);
  if (forms.genus != 1)
    throw InputError("the " + name + " has genus " + std::to_string(forms.genus) +
                     ": matching covers genus 0 and 1 so far");
  TorusOfSurface out;
  FlatTorus flat = flat_torus(work, build_mesh_edges(work), forms.normalized.front(),
                              forms.riemann_matrix(0, 0));
  if (set_aside) { // back on the input's vertices and faces
    const Eigen::Vector2d none = Eigen::Vector2d::Constant(std::nan(""));
    FlatTorus on_input{flat.tau, {}, {}, {}};
    for (int w : aside.vertex_in_work)
      on_input.vertex.push_back(w >= 0 ? flat.vertex[size_t(w)] : none);
    for (int w : aside.face_in_work) {
      on_input.faces.push_back(w >= 0 ? flat.faces[size_t(w)]
                                      : std::array<Eigen::Vector2d, 3>{none, none, none});
      on_input.face_areas.push_back(w >= 0 ? flat.face_areas[size_t(w)] : 0.0);
    }
    flat = std::move(on_input);
  }
  out.torus = std::move(flat);
  MappedSurface &surface = out.surface;
  surface.positions = positions_of(mesh);
  surface.faces = surface.input_faces = triangles_of(mesh);
  for (size_t f = 0; f < surface.faces.size(); ++f) {
    surface.face_source.push_back(int(f));
    for (int k = 0; k < 3; ++k)
      out.face_corners.push_back(surface.faces[f][size_t(k)]);
  }
  surface.diagonal = diagonal_of(surface.positions);
  out.factor = log_conformal_factor(surface.positions, surface.faces, out.torus.face_areas);
  return out;
}

// b1, b2 of p in the (coplanar) triangle abc.
Eigen::Vector2d barycentric(const Eigen::Vector3d &p, const Eigen::Vector3d &a,
                            const Eigen::Vector3d &b, const Eigen::Vector3d &c) {
  const Eigen::Vector3d u = b - a, v = c - a, w = p - a;
  const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v), wu = w.dot(u), wv = w.dot(v);
  const double det = uu * vv - uv * uv;
  if (!(std::abs(det) > 0)) return {0, 0};
  return {(vv * wu - uv * wv) / det, (uu * wv - uv * wu) / det};
}

// The points of `to` whose sphere points are `images`, with the written triangle each lies in and
// its weights there.
struct Located {
  MatchedPoints points;
  std::vector<int> written_face;
  std::vector<Eigen::Vector3d> written_weights;
};

// `holding(v)`: the written triangle of `to` that holds image v, and the weights there.
template <class Holding>
Located located(const MappedSurface &to, size_t count, const Holding &holding) {
  const size_t image_count = count;
  Located located;
  located.written_face.assign(image_count, -1);
  located.written_weights.assign(image_count, Eigen::Vector3d::Zero());
  MatchedPoints &out = located.points;
  out.target_face.assign(image_count, -1);
  out.weights.assign(image_count, Eigen::Vector2d::Zero());
  out.position.assign(image_count, Eigen::Vector3d::Constant(std::nan("")));
  parallel_for(image_count, [&](size_t v) {
    const std::pair<int, Eigen::Vector3d> found = holding(v);
    const struct {
      int triangle;
      Eigen::Vector3d weights;
    } hold{found.first, found.second};
    if (hold.triangle < 0) return;
    const auto &face = to.faces[size_t(hold.triangle)];
    const Eigen::Vector3d p = hold.weights[0] * to.positions[size_t(face[0])] +
                              hold.weights[1] * to.positions[size_t(face[1])] +
                              hold.weights[2] * to.positions[size_t(face[2])];
    located.written_face[v] = hold.triangle;
    located.written_weights[v] = hold.weights;
    const int input_face = to.face_source[size_t(hold.triangle)];
    const auto &corners = to.input_faces[size_t(input_face)];
    out.target_face[v] = input_face;
    out.position[v] = p;
    out.weights[v] =
        barycentric(p, to.positions[size_t(corners[0])], to.positions[size_t(corners[1])],
                    to.positions[size_t(corners[2])]);
  });
  return located;
}

void check_landmarks(const std::vector<std::pair<int, int>> &landmarks, size_t source_vertices,
                     size_t target_vertices) {
  for (size_t k = 0; k < landmarks.size(); ++k) {
    const auto [i, j] = landmarks[k];
    if (i < 0 || size_t(i) >= source_vertices || j < 0 || size_t(j) >= target_vertices)
      throw InputError("landmark pair " + std::to_string(k + 1) + " (" + std::to_string(i) + " " +
                       std::to_string(j) + ") names a vertex that is not there: the source has " +
                       std::to_string(source_vertices) + " vertices, the target " +
                       std::to_string(target_vertices));
  }
}

// Landmarks, angle error and folds of the matched mesh (SOURCE's triangles on the points).
void measure_matched_mesh(const MappedSurface &from, const MappedSurface &to,
                          const std::vector<std::pair<int, int>> &landmarks, SurfaceMatch &out) {
  for (size_t v = 0; v < out.forward.target_face.size(); ++v)
    out.unmatched_vertices += out.forward.target_face[v] < 0;
  // Landmarks: where the source's landed against the target's own vertex.
  for (const auto &[i, j] : landmarks) {
    const double d =
        (out.forward.position[size_t(i)] - to.positions[size_t(j)]).norm() / to.diagonal;
    out.landmark_residual_max = std::max(out.landmark_residual_max, std::isnan(d) ? 1.0 : d);
    out.landmark_residual_mean += (std::isnan(d) ? 1.0 : d) / double(landmarks.size());
  }
  double angle_sum = 0;
  long long corners = 0;
  for (const auto &face : from.input_faces) {
    const Eigen::Vector3d p[3] = {out.forward.position[size_t(face[0])],
                                  out.forward.position[size_t(face[1])],
                                  out.forward.position[size_t(face[2])]};
    const Eigen::Vector3d s[3] = {from.positions[size_t(face[0])], from.positions[size_t(face[1])],
                                  from.positions[size_t(face[2])]};
    if (!(p[0].allFinite() && p[1].allFinite() && p[2].allFinite())) continue;
    const Eigen::Vector3d normal = (p[1] - p[0]).cross(p[2] - p[0]);
    if (normal.norm() <= 1e-14 * (p[1] - p[0]).squaredNorm()) continue; // flat: not turned over
    // Turned over: against the target surface's normal where each of its corners lies (a chord
    // across a crease may disagree with the face at one corner; a turned triangle with all).
    bool against_all = true;
    for (int k = 0; k < 3; ++k) {
      const auto &t = to.input_faces[size_t(out.forward.target_face[size_t(face[size_t(k)])])];
      const Eigen::Vector3d surface_normal =
          (to.positions[size_t(t[1])] - to.positions[size_t(t[0])])
              .cross(to.positions[size_t(t[2])] - to.positions[size_t(t[0])]);
      against_all = against_all && normal.dot(surface_normal) < 0;
    }
    out.folded_faces += against_all;
    for (int k = 0; k < 3; ++k) {
      angle_sum += std::abs(corner_angle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]) -
                            corner_angle(s[k], s[(k + 1) % 3], s[(k + 2) % 3]));
      ++corners;
    }
  }
  out.angle_error_mean_degrees = corners ? angle_sum / double(corners) * 180 / M_PI : 0;
}

// Each source triangle on the target triangle that `centre_hold(f)` finds for the image of its
// centre (a written triangle of `to` and weights), with its corners' matched points in that
// triangle's weights.
template <class CentreHold>
void match_faces(const MappedSurface &from, const MappedSurface &to, const CentreHold &centre_hold,
                 SurfaceMatch &out) {
  out.faces.assign(from.input_faces.size(), FaceMatch{});
  parallel_for(from.input_faces.size(), [&](size_t f) {
    const int written = centre_hold(f).first;
    if (written < 0) return;
    const int face = to.face_source[size_t(written)];
    const auto &t = to.input_faces[size_t(face)];
    FaceMatch match{face, {}};
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d &p = out.forward.position[size_t(from.input_faces[f][size_t(k)])];
      const Eigen::Vector2d b = barycentric(p, to.positions[size_t(t[0])],
                                            to.positions[size_t(t[1])], to.positions[size_t(t[2])]);
      match.weights[size_t(k)] = Eigen::Vector3d(1 - b[0] - b[1], b[0], b[1]);
      if (!match.weights[size_t(k)].allFinite()) return;
    }
    out.faces[f] = match;
  });
}

// The round trip: a source vertex's point on the target, carried back by the target's written
// vertices' points on the source; the target's input vertices' points become `out.backward`.
void measure_round_trip(const MappedSurface &from, const MappedSurface &to, const Located &forward,
                        Located backward, size_t target_vertices, SurfaceMatch &out) {
  double sum = 0, worst = 0;
  long long counted = 0;
  for (size_t v = 0; v < forward.written_face.size(); ++v) {
    const int face = forward.written_face[v];
    if (face < 0) continue;
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
      p += forward.written_weights[v][k] *
           backward.points.position[size_t(to.faces[size_t(face)][size_t(k)])];
    const double d = p.allFinite() ? (p - from.positions[v]).norm() / from.diagonal : 1.0;
    sum += d, worst = std::max(worst, d), ++counted;
  }
  out.round_trip_mean = counted ? sum / double(counted) : -1;
  out.round_trip_max = counted ? worst : -1;
  MatchedPoints &points = backward.points;
  points.target_face.resize(target_vertices);
  points.weights.resize(target_vertices);
  points.position.resize(target_vertices);
  out.backward = std::move(points);
}

using Clock = std::chrono::steady_clock;
double since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

SurfaceMatch match_spheres(Mesh &source, Mesh &target, const MatchOptions &options,
                           const Progress &progress) {
  SurfaceMatch out;
  auto start = Clock::now();
  const MappedSurface from = genus0_sphere(source, "source", progress.range(0.0, 0.4));
  out.timings_ms.emplace_back("map source", since(start));
  start = Clock::now();
  const MappedSurface to = genus0_sphere(target, "target", progress.range(0.4, 0.8));
  out.timings_ms.emplace_back("map target", since(start));
  progress.report(0.8, "aligning the spheres");

  start = Clock::now();
  const SphereTriangleGrid target_grid(to.sphere, to.faces);
  // The source's sphere triangles are searched by the automatic alignment and the match back only.
  std::optional<SphereTriangleGrid> source_grid;
  if (options.landmarks.empty() || options.both) source_grid.emplace(from.sphere, from.faces);
  if (!options.landmarks.empty()) {
    out.alignment = align_by_landmarks(from.sphere, to.sphere, options.landmarks);
  } else {
    const std::vector<double> source_factor =
        log_conformal_factor(from.positions, from.faces, sphere_face_areas(from));
    const std::vector<double> target_factor =
        log_conformal_factor(to.positions, to.faces, sphere_face_areas(to));
    out.alignment = align_by_functions({from.faces, *source_grid, source_factor},
                                       {to.faces, target_grid, target_factor});
  }
  out.timings_ms.emplace_back("align", since(start));
  progress.report(0.9, "matching the vertices");

  start = Clock::now();
  const auto held = [](const SphereTriangleGrid &grid, const Eigen::Vector3d &p) {
    const SphereTriangleGrid::Hold hold = grid.holding_with_weights(p);
    return std::make_pair(hold.triangle, hold.weights);
  };
  const Located forward = located(to, source.vert.size(), [&](size_t v) {
    return held(target_grid, out.alignment.apply(from.sphere[v]));
  });
  out.forward = forward.points;
  match_faces(
      from, to,
      [&](size_t f) {
        const auto &t = from.input_faces[f];
        const Eigen::Vector3d centre =
            (from.sphere[size_t(t[0])] + from.sphere[size_t(t[1])] + from.sphere[size_t(t[2])])
                .normalized();
        return held(target_grid, out.alignment.apply(centre));
      },
      out);
  measure_matched_mesh(from, to, options.landmarks, out);
  if (options.both) {
    // The target's written vertices matched back (the alignment undone).
    Located backward = located(from, to.sphere.size(), [&](size_t v) {
      return held(*source_grid, out.alignment.apply_inverse(to.sphere[v]));
    });
    measure_round_trip(from, to, forward, std::move(backward), target.vert.size(), out);
  }
  out.timings_ms.emplace_back("match", since(start));
  out.genus = 0;
  return out;
}

SurfaceMatch match_tori(const Mesh &source, const Mesh &target, const MatchOptions &options,
                        const Progress &progress) {
  SurfaceMatch out;
  auto start = Clock::now();
  const TorusOfSurface from = genus1_torus(source, "source", progress.range(0.0, 0.4));
  out.timings_ms.emplace_back("map source", since(start));
  start = Clock::now();
  const TorusOfSurface to = genus1_torus(target, "target", progress.range(0.4, 0.8));
  out.timings_ms.emplace_back("map target", since(start));
  progress.report(0.8, "aligning the tori");

  start = Clock::now();
  const FlatTorusLocator source_locator(from.torus), target_locator(to.torus);
  out.torus = align_tori({from.torus, source_locator, from.face_corners, from.factor},
                         {to.torus, target_locator, to.face_corners, to.factor}, options.landmarks);
  out.source_modulus = from.torus.tau;
  out.target_modulus = to.torus.tau;
  out.timings_ms.emplace_back("align", since(start));
  progress.report(0.9, "matching the vertices");

  start = Clock::now();
  const auto held = [](const FlatTorusLocator &locator, const Eigen::Vector2d &p) {
    const FlatTorusLocator::Hold hold = locator.holding(p);
    return std::make_pair(hold.face, hold.weights);
  };
  const Located forward = located(to.surface, source.vert.size(), [&](size_t v) {
    return held(target_locator, out.torus.apply(from.torus.vertex[v]));
  });
  out.forward = forward.points;
  match_faces(
      from.surface, to.surface,
      [&](size_t f) {
        const auto &corners = from.torus.faces[f];
        return held(target_locator, out.torus.apply((corners[0] + corners[1] + corners[2]) / 3));
      },
      out);
  measure_matched_mesh(from.surface, to.surface, options.landmarks, out);
  if (options.both) {
    Located backward = located(from.surface, target.vert.size(), [&](size_t v) {
      return held(source_locator, out.torus.apply_inverse(to.torus.vertex[v]));
    });
    measure_round_trip(from.surface, to.surface, forward, std::move(backward), target.vert.size(),
                       out);
  }
  out.timings_ms.emplace_back("match", since(start));
  out.genus = 1;
  return out;
}

} // namespace

SurfaceMatch match_surfaces(Mesh &source, Mesh &target, const MatchOptions &options,
                            const Progress &progress) {
  check_landmarks(options.landmarks, source.vert.size(), target.vert.size());
  const int source_genus = closed_genus_estimate(source),
            target_genus = closed_genus_estimate(target);
  if (source_genus == 1 && target_genus == 1) return match_tori(source, target, options, progress);
  if ((source_genus == 1) != (target_genus == 1))
    throw InputError("the source looks like genus " + std::to_string(source_genus) +
                     " and the target genus " + std::to_string(target_genus) +
                     " (from their vertex and face counts): a match takes two closed surfaces of "
                     "the same genus");
  return match_spheres(source, target, options, progress);
}

} // namespace meromorph
