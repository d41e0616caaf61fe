#include "match/surface_match.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/Geometry>

#include "common/errors.h"
#include "common/parallel_for.h"
#include "forms/holomorphic_pipeline.h"
#include "job/set_aside.h"
#include "job/surface_map.h"
#include "maps/parameterization.h"
#include "match/flat_torus.h"
#include "match/sheet_following.h"
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
  std::vector<Eigen::Vector3d> branch_values; // genus 2: the six Weierstrass points' values
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

// A mesh as the match reads it, validated once: with defects to set aside (job/set_aside.h), the
// work mesh without them; the genus from V - E + F of the work mesh (a closed triangle mesh, each
// edge on two faces: 2 - 2 genus when it is one part).
struct ReadMesh {
  const Mesh &input;
  SetAside aside;
  bool set_aside = false;
  int genus = 0;
  explicit ReadMesh(const Mesh &mesh) : input(mesh) {
    const Validation validation = validate_mesh(mesh);
    set_aside = has_defects_to_set_aside(validation);
    if (set_aside) set_aside_defects(mesh, validation, aside);
    genus = (2 - (int(work().vert.size()) - int(work().face.size()) / 2)) / 2;
  }
  const Mesh &work() const { return set_aside ? aside.work : input; }
};

// The surface's map as `param` writes it (genus 0: the sphere; genus 2: the canonical,
// hyperelliptic map, unique up to a Moebius transformation), refused unless of `genus`.
MappedSurface sphere_map(Mesh &mesh, const char *which, const Progress &progress, int genus) {
  const Parameterization map = parameterize_surface(mesh, ParameterizeOptions{}, progress);
  const std::string name = which;
  if (map.components.size() > 1)
    throw InputError("the " + name + " has " + std::to_string(map.components.size()) +
                     " parts: a match takes one closed surface; map its parts apart");
  if (map.genus != genus)
    throw InputError("the " + name + " has genus " + std::to_string(map.genus) +
                     (genus == 0 && map.genus > 2
                          ? ": matching covers genus 0, 1 and 2 so far (both surfaces closed, of "
                            "the same genus)"
                          : ", the other genus " + std::to_string(genus) +
                                ": a match takes two closed surfaces of the same genus"));
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
  for (const BranchPoint &branch : map.branch_points)
    out.branch_values.push_back(branch.sphere);
  return out;
}

// The point of the sphere at the centre of the image of the surface's input face f.
Eigen::Vector3d sphere_centre(const MappedSurface &surface, size_t f) {
  const auto &t = surface.input_faces[f];
  return (surface.sphere[size_t(t[0])] + surface.sphere[size_t(t[1])] +
          surface.sphere[size_t(t[2])])
      .normalized();
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
  std::vector<double> factor; // log conformal factor per vertex
};

// The flat torus is computed on the mesh with its defects set aside (job/set_aside.h: seam
// duplicates welded, doubled faces and vertices on no face left out) and read back on the input's
// own vertices and faces; those left out get no flat point (no match, and found by nothing).
TorusOfSurface genus1_torus(const ReadMesh &read, const char *which, const Progress &progress) {
  const std::string name = which;
  const Mesh &mesh = read.input, &work = read.work();
  const SetAside &aside = read.aside;
  const bool set_aside = read.set_aside;
  const HolomorphicForms forms = compute_holomorphic_forms(work, SolverKind::cholmod, progress);
  if (forms.genus != 1)
    throw InputError("the " + name + " has genus " + std::to_string(forms.genus) +
                     ": matching covers genus 0, 1 and 2 so far");
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
  for (size_t f = 0; f < surface.faces.size(); ++f)
    surface.face_source.push_back(int(f));
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
Located located(const MappedSurface &to, size_t image_count, const Holding &holding) {
  Located located;
  located.written_face.assign(image_count, -1);
  located.written_weights.assign(image_count, Eigen::Vector3d::Zero());
  MatchedPoints &out = located.points;
  out.target_face.assign(image_count, -1);
  out.weights.assign(image_count, Eigen::Vector2d::Zero());
  out.position.assign(image_count, Eigen::Vector3d::Constant(std::nan("")));
  parallel_for(image_count, [&](size_t v) {
    const auto [triangle, weights] = holding(v);
    if (triangle < 0) return;
    const auto &face = to.faces[size_t(triangle)];
    const Eigen::Vector3d p = weights[0] * to.positions[size_t(face[0])] +
                              weights[1] * to.positions[size_t(face[1])] +
                              weights[2] * to.positions[size_t(face[2])];
    located.written_face[v] = triangle;
    located.written_weights[v] = weights;
    const int input_face = to.face_source[size_t(triangle)];
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

// `map(mesh, "source" or "target", progress)` of each surface in turn, timed into `out`.
template <class SomeMesh, class Map>
auto both_mapped(SomeMesh &source, SomeMesh &target, const Map &map, const Progress &progress,
                 SurfaceMatch &out) {
  auto start = Clock::now();
  auto from = map(source, "source", progress.range(0.0, 0.4));
  out.timings_ms.emplace_back("map source", since(start));
  start = Clock::now();
  auto to = map(target, "target", progress.range(0.4, 0.8));
  out.timings_ms.emplace_back("map target", since(start));
  return std::make_pair(std::move(from), std::move(to));
}

std::pair<MappedSurface, MappedSurface> both_sphere_maps(Mesh &source, Mesh &target, int genus,
                                                         const Progress &progress,
                                                         SurfaceMatch &out) {
  return both_mapped(
      source, target,
      [genus](Mesh &mesh, const char *which, const Progress &part) {
        return sphere_map(mesh, which, part, genus);
      },
      progress, out);
}

SurfaceMatch match_spheres(Mesh &source, Mesh &target, const MatchOptions &options,
                           const Progress &progress) {
  SurfaceMatch out;
  const auto maps = both_sphere_maps(source, target, 0, progress, out);
  const MappedSurface &from = maps.first, &to = maps.second;
  progress.report(0.8, "aligning the spheres");
  auto start = Clock::now();
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
      [&](size_t f) { return held(target_grid, out.alignment.apply(sphere_centre(from, f))); },
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

SurfaceMatch match_tori(const ReadMesh &source, const ReadMesh &target, const MatchOptions &options,
                        const Progress &progress) {
  SurfaceMatch out;
  const auto tori = both_mapped(source, target, genus1_torus, progress, out);
  const TorusOfSurface &from = tori.first, &to = tori.second;
  progress.report(0.8, "aligning the tori");
  auto start = Clock::now();
  const FlatTorusLocator source_locator(from.torus), target_locator(to.torus);
  out.torus =
      align_tori({from.torus, source_locator, from.surface.faces, from.factor},
                 {to.torus, target_locator, to.surface.faces, to.factor}, options.landmarks);
  out.source_modulus = from.torus.tau;
  out.target_modulus = to.torus.tau;
  out.timings_ms.emplace_back("align", since(start));
  progress.report(0.9, "matching the vertices");

  start = Clock::now();
  const auto held = [](const FlatTorusLocator &locator, const Eigen::Vector2d &p) {
    const FlatTorusLocator::Hold hold = locator.holding(p);
    return std::make_pair(hold.face, hold.weights);
  };
  const Located forward = located(to.surface, from.surface.positions.size(), [&](size_t v) {
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
    const size_t target_vertices = to.surface.positions.size();
    Located backward = located(from.surface, target_vertices, [&](size_t v) {
      return held(source_locator, out.torus.apply_inverse(to.torus.vertex[v]));
    });
    measure_round_trip(from.surface, to.surface, forward, std::move(backward), target_vertices,
                       out);
  }
  out.timings_ms.emplace_back("match", since(start));
  out.genus = 1;
  return out;
}

// The vertices next to each vertex of `faces`.
std::vector<std::vector<int>> neighbours_of(const std::vector<std::array<int, 3>> &faces,
                                            size_t vertex_count) {
  std::vector<std::vector<int>> out(vertex_count);
  for (const auto &t : faces)
    for (int k = 0; k < 3; ++k) {
      out[size_t(t[size_t(k)])].push_back(t[size_t((k + 1) % 3)]);
      out[size_t(t[size_t(k)])].push_back(t[size_t((k + 2) % 3)]);
    }
  for (auto &list : out) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return out;
}

// Where the image of each vertex lies on `to`, one per sheet: its written triangles that hold the
// point (duplicates where it falls on an edge dropped), their weights and points.
struct Preimages {
  std::vector<std::vector<int>> face;
  std::vector<std::vector<Eigen::Vector3d>> weights, point;
};

Preimages preimages(const MappedSurface &to, const SphereTriangleGrid &grid,
                    const std::vector<Eigen::Vector3d> &images) {
  Preimages out;
  out.face.resize(images.size()), out.weights.resize(images.size());
  out.point.resize(images.size());
  parallel_for(images.size(), [&](size_t v) {
    const Eigen::Vector3d &p = images[v];
    grid.for_each_holding(p, [&](int f) {
      const auto &t = to.faces[size_t(f)];
      const Eigen::Vector3d w = grid.weights_in(f, p);
      const Eigen::Vector3d q = w[0] * to.positions[size_t(t[0])] +
                                w[1] * to.positions[size_t(t[1])] +
                                w[2] * to.positions[size_t(t[2])];
      for (const Eigen::Vector3d &seen : out.point[v])
        if ((seen - q).norm() <= 1e-9 * to.diagonal) return;
      out.face[v].push_back(f), out.weights[v].push_back(w), out.point[v].push_back(q);
    });
  });
  return out;
}

// The vertex whose preimages are farthest apart (its sheets clearly told apart): the seed.
int clearest_vertex(const Preimages &on) {
  int best = -1;
  double apart = -1;
  for (size_t v = 0; v < on.point.size(); ++v)
    if (on.point[v].size() >= 2 && (on.point[v][0] - on.point[v][1]).norm() > apart)
      apart = (on.point[v][0] - on.point[v][1]).norm(), best = int(v);
  return best;
}

Located chosen_points(const MappedSurface &to, const Preimages &on,
                      const std::vector<int> &chosen) {
  return located(to, chosen.size(), [&](size_t v) {
    return chosen[v] < 0
               ? std::make_pair(-1, Eigen::Vector3d(Eigen::Vector3d::Zero()))
               : std::make_pair(on.face[v][size_t(chosen[v])], on.weights[v][size_t(chosen[v])]);
  });
}

// Genus 2: both surfaces' canonical (hyperelliptic) maps, degree 2 with six branch values, which
// differ by a Moebius transformation when the conformal structures are the same: every Moebius
// transformation that takes the six values onto the six, each with the two ways of choosing the
// sheets (the hyperelliptic involution), judged by the landmarks or by the log conformal factors.
SurfaceMatch match_genus_two(Mesh &source, Mesh &target, const MatchOptions &options,
                             const Progress &progress) {
  SurfaceMatch out;
  const auto maps = both_sphere_maps(source, target, 2, progress, out);
  const MappedSurface &from = maps.first, &to = maps.second;
  progress.report(0.8, "matching the branch values");
  if (from.branch_values.size() != 6 || to.branch_values.size() != 6)
    throw InputError("a genus-2 match needs the six simple branch points of each surface's map; "
                     "the source's has " +
                     std::to_string(from.branch_values.size()) + ", the target's " +
                     std::to_string(to.branch_values.size()));
  auto start = Clock::now();
  std::vector<SphereAlignment> candidates =
      align_point_sets(from.branch_values, to.branch_values, 0.05);
  if (candidates.empty())
    throw InputError("no Moebius transformation takes the source's six branch values onto the "
                     "target's: the two surfaces are not of the same conformal structure (a "
                     "genus-2 match needs them to be)");
  // All within the tolerance, not only the best fits: on a symmetric surface a permutation of the
  // values can fit better than the true correspondence, which the two triangulations' maps give
  // only to their discretization (the maps decide below).
  const SphereTriangleGrid target_grid(to.sphere, to.faces);
  const size_t n = source.vert.size();
  const std::vector<std::vector<int>> neighbours = neighbours_of(from.input_faces, n);
  const std::vector<double> source_factor =
      log_conformal_factor(from.positions, from.faces, sphere_face_areas(from));
  const std::vector<double> target_factor =
      log_conformal_factor(to.positions, to.faces, sphere_face_areas(to));
  // The target's factor at preimage q of entry k of `on`.
  const auto factor_at = [&](const Preimages &on, size_t k, size_t q) {
    const auto &t = to.faces[size_t(on.face[k][q])];
    const Eigen::Vector3d &w = on.weights[k][q];
    return w[0] * target_factor[size_t(t[0])] + w[1] * target_factor[size_t(t[1])] +
           w[2] * target_factor[size_t(t[2])];
  };
  struct Trial {
    size_t candidate;
    std::vector<int> chosen;
    double cost, landmark_distance; // log conformal factors' mismatch; landmarks / diagonal
  };
  // A first look at every candidate on about 500 vertices, whatever their sheet (each at its
  // preimage that fits best, and the landmarks likewise): the best go on to the whole surface.
  {
    std::vector<size_t> sample;
    for (size_t v = 0; v < n; v += std::max<size_t>(1, n / 500))
      sample.push_back(v);
    for (const auto &[i, j] : options.landmarks)
      sample.push_back(size_t(i));
    std::vector<std::pair<std::pair<double, double>, size_t>> scored; // ((landmarks, factors), c)
    for (size_t c = 0; c < candidates.size(); ++c) {
      std::vector<Eigen::Vector3d> images;
      for (size_t v : sample)
        images.push_back(candidates[c].apply(from.sphere[v]));
      const Preimages on = preimages(to, target_grid, images);
      double factors = 0, landmarks = 0;
      for (size_t k = 0; k < sample.size(); ++k) {
        double fit = std::numeric_limits<double>::infinity();
        for (size_t q = 0; q < on.face[k].size(); ++q)
          fit = std::min(fit, std::pow(source_factor[sample[k]] - factor_at(on, k, q), 2));
        factors += std::isfinite(fit) ? fit : 1.0;
      }
      for (size_t l = 0; l < options.landmarks.size(); ++l) {
        const size_t k = sample.size() - options.landmarks.size() + l;
        double nearest = 1.0;
        for (const Eigen::Vector3d &q : on.point[k])
          nearest =
              std::min(nearest, (q - to.positions[size_t(options.landmarks[l].second)]).norm() /
                                    to.diagonal);
        landmarks += nearest;
      }
      scored.push_back({{landmarks, factors}, c});
    }
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto &entry : scored)
      nearest = std::min(nearest, entry.first.first);
    std::sort(scored.begin(), scored.end(), [&](const auto &a, const auto &b) {
      const bool a_meets = a.first.first <= nearest + 0.01,
                 b_meets = b.first.first <= nearest + 0.01;
      return a_meets != b_meets ? a_meets : a.first.second < b.first.second;
    });
    std::vector<SphereAlignment> kept;
    // Those within three times the best first look (the surface's symmetries fit as well; a
    // wrong correspondence of the values costs many times more), four at the most.
    for (size_t k = 0; k < scored.size() && k < 4; ++k)
      if (k == 0 || (scored[k].first.first <= nearest + 0.01 &&
                     scored[k].first.second <= 3 * scored[0].first.second + 1e-12))
        kept.push_back(candidates[scored[k].second]);
    candidates = std::move(kept);
  }
  std::vector<Trial> trials;
  std::vector<Preimages> found;
  for (size_t c = 0; c < candidates.size(); ++c) {
    std::vector<Eigen::Vector3d> images(n);
    parallel_for(n, [&](size_t v) { images[v] = candidates[c].apply(from.sphere[v]); });
    found.push_back(preimages(to, target_grid, images));
    const Preimages &on = found.back();
    const int seed = clearest_vertex(on);
    for (int choice = 0; choice < 2 && seed >= 0; ++choice) {
      Trial trial{c, follow_sheets(on.point, neighbours, seed, choice), 0, 0};
      double cost = 0;
      long long counted = 0;
      for (size_t v = 0; v < n; ++v) {
        const int k = trial.chosen[v];
        if (k < 0) continue;
        cost += std::pow(source_factor[v] - factor_at(on, v, size_t(k)), 2);
        ++counted;
      }
      for (const auto &[i, j] : options.landmarks) {
        const int k = trial.chosen[size_t(i)];
        trial.landmark_distance +=
            (k < 0 ? 1.0
                   : (on.point[size_t(i)][size_t(k)] - to.positions[size_t(j)]).norm() /
                         to.diagonal) /
            double(options.landmarks.size());
      }
      trial.cost = counted ? cost / double(counted) : 1e300;
      trials.push_back(std::move(trial));
    }
  }
  if (trials.empty())
    throw InputError("the source's vertices find no points of the target through the two maps");
  // With landmarks, those that meet them within 1% of the diagonal of the best, then the factors.
  double nearest_landmarks = std::numeric_limits<double>::infinity();
  for (const Trial &trial : trials)
    nearest_landmarks = std::min(nearest_landmarks, trial.landmark_distance);
  trials.erase(std::remove_if(trials.begin(), trials.end(),
                              [&](const Trial &trial) {
                                return trial.landmark_distance > nearest_landmarks + 0.01;
                              }),
               trials.end());
  std::sort(trials.begin(), trials.end(),
            [](const Trial &a, const Trial &b) { return a.cost < b.cost; });
  const Trial &best = trials.front();
  out.alignment = candidates[best.candidate];
  out.alignment.cost = best.cost;
  out.alignment.method =
      options.landmarks.empty()
          ? "genus 2: the canonical maps' six branch values matched by a Moebius transformation, "
            "the sheets followed from one vertex, chosen by the log conformal factors"
          : "genus 2: the canonical maps' six branch values matched by a Moebius transformation, "
            "the sheets followed from one vertex, chosen by the landmarks, then the log "
            "conformal factors";
  for (size_t k = 1; k < trials.size(); ++k)
    if (trials[k].cost <= 3 * best.cost + 1e-12)
      out.alignment.alternatives.push_back({0, trials[k].cost});
  out.timings_ms.emplace_back("align", since(start));
  progress.report(0.9, "matching the vertices");

  start = Clock::now();
  const Preimages &on = found[best.candidate];
  const Located forward = chosen_points(to, on, best.chosen);
  out.forward = forward.points;
  match_faces(
      from, to,
      [&](size_t f) {
        // The target triangle among the centre's preimages nearest the corners' matched points.
        const auto &t = from.input_faces[f];
        const Preimages centre_on =
            preimages(to, target_grid, {out.alignment.apply(sphere_centre(from, f))});
        Eigen::Vector3d corners = Eigen::Vector3d::Zero();
        int known = 0;
        for (int k = 0; k < 3; ++k)
          if (out.forward.target_face[size_t(t[size_t(k)])] >= 0)
            corners += out.forward.position[size_t(t[size_t(k)])], ++known;
        std::pair<int, Eigen::Vector3d> hold{-1, Eigen::Vector3d::Zero()};
        double nearest = std::numeric_limits<double>::infinity();
        for (size_t k = 0; k < centre_on.point[0].size() && known > 0; ++k) {
          const double d = (centre_on.point[0][k] - corners / known).norm();
          if (d < nearest) nearest = d, hold = {centre_on.face[0][k], centre_on.weights[0][k]};
        }
        return hold;
      },
      out);
  measure_matched_mesh(from, to, options.landmarks, out);
  if (options.both) {
    // Back: the inverse transformation, the sheets followed from the target vertex nearest the
    // forward seed's point, its choice the preimage nearest that seed.
    const SphereTriangleGrid source_grid(from.sphere, from.faces);
    std::vector<Eigen::Vector3d> images(to.sphere.size());
    parallel_for(images.size(),
                 [&](size_t v) { images[v] = out.alignment.apply_inverse(to.sphere[v]); });
    const Preimages back_on = preimages(from, source_grid, images);
    const int seed = clearest_vertex(on);
    const int face = seed >= 0 ? forward.written_face[size_t(seed)] : -1;
    int target_seed = -1, choice = -1;
    if (face >= 0) {
      const Eigen::Vector3d &w = forward.written_weights[size_t(seed)];
      int corner = 0;
      w.maxCoeff(&corner);
      target_seed = to.faces[size_t(face)][size_t(corner)];
      double nearest = std::numeric_limits<double>::infinity();
      for (size_t k = 0; k < back_on.point[size_t(target_seed)].size(); ++k) {
        const double d =
            (back_on.point[size_t(target_seed)][k] - from.positions[size_t(seed)]).norm();
        if (d < nearest) nearest = d, choice = int(k);
      }
    }
    const std::vector<int> back_chosen =
        choice < 0 ? std::vector<int>(to.sphere.size(), -1)
                   : follow_sheets(back_on.point, neighbours_of(to.faces, to.sphere.size()),
                                   target_seed, choice);
    measure_round_trip(from, to, forward, chosen_points(from, back_on, back_chosen),
                       target.vert.size(), out);
  }
  out.timings_ms.emplace_back("match", since(start));
  out.genus = 2;
  return out;
}

} // namespace

SurfaceMatch match_surfaces(Mesh &source, Mesh &target, const MatchOptions &options,
                            const Progress &progress) {
  check_landmarks(options.landmarks, source.vert.size(), target.vert.size());
  const ReadMesh source_read(source), target_read(target);
  const int source_genus = source_read.genus, target_genus = target_read.genus;
  if (source_genus == 1 && target_genus == 1)
    return match_tori(source_read, target_read, options, progress);
  if (source_genus == 2 && target_genus == 2)
    return match_genus_two(source, target, options, progress);
  if ((source_genus == 1) != (target_genus == 1) || (source_genus == 2) != (target_genus == 2))
    throw InputError("the source looks like genus " + std::to_string(source_genus) +
                     " and the target genus " + std::to_string(target_genus) +
                     " (from their vertex and face counts): a match takes two closed surfaces of "
                     "the same genus");
  return match_spheres(source, target, options, progress);
}

} // namespace meromorph
