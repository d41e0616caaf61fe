#include "maps/parameterization.h"

#include <chrono>
#include <functional>
#include <optional>
#include <set>
#include <sstream>

#include "common/errors.h"
#include "common/wording.h"
#include "forms/holomorphic_pipeline.h"
#include "maps/branch_snapping.h"
#include "maps/fold_untangling.h"
#include "maps/form_pairs.h"
#include "maps/form_ratio_map.h"
#include "maps/genus0_correction.h"
#include "maps/genus0_map.h"
#include "maps/genus1_branch_placement.h"
#include "maps/genus1_map.h"
#include "mesh/face_vectors.h"
#include "mesh/unit_scale.h"
#include "sphere/branch_points.h"

namespace meromorph {
namespace {

// Faces whose image is below double resolution (sphere_geometry.h).
int collapsed_faces(const Mesh &mesh, const std::vector<PlaneValue> &values) {
  int count = 0;
  for (const MeshFace &face : mesh.face)
    count += collapsed_image(to_sphere(values[size_t(index_of(mesh, face.cV(0)))]),
                             to_sphere(values[size_t(index_of(mesh, face.cV(1)))]),
                             to_sphere(values[size_t(index_of(mesh, face.cV(2)))]));
  return count;
}

// What keeps the written map from being a valid branched cover of the sphere.
std::vector<std::string> invalid_reasons(const ParameterizeOptions &options,
                                         const Parameterization &map) {
  std::vector<std::string> reasons;
  const int expected = map.genus == 0 ? 1 : map.genus == 1 ? 2 : 2 * map.genus - 2;
  const bool chosen_pair = map.genus >= 2 && options.form_pair[0] >= 0;
  if (chosen_pair ? (map.degree < 1 || map.degree > expected) : map.degree != expected)
    reasons.push_back("the map covers the sphere " + std::to_string(map.degree) +
                      " times instead of " + std::to_string(expected));
  if (!map.riemann_hurwitz_ok)
    reasons.push_back(
        "Riemann-Hurwitz does not hold (chi = " + std::to_string(map.euler) +
        ", 2 * degree - ramification = " + std::to_string(2 * map.degree - map.ramification) +
        "): branch points were missed or are wrong");
  const std::vector<int> &folded = map.quality.folded_face_indices;
  if (!folded.empty())
    reasons.push_back(folded.size() == 1
                          ? "1 face is turned over (face " + list_indices(folded) + ")"
                          : std::to_string(folded.size()) + " faces are turned over (faces " +
                                list_indices(folded) + ")");
  // Where faces shrink below what doubles resolve, that is the cause of the rest: said first.
  const size_t collapsed = map.quality.collapsed_face_indices.size();
  if (!reasons.empty() && collapsed > 0)
    reasons.insert(reasons.begin(), plural(collapsed, "face shrinks", "faces shrink") +
                                        " below what double precision resolves (long "
                                        "thin parts: see below)");
  return reasons;
}

// What a user can do when the map is not valid, from what this mesh and map show.
// `mesh` is the unit-scale copy; places are given in `input`'s coordinates.
std::string invalid_map_advice(const Mesh &input, const Mesh &mesh,
                               const ParameterizeOptions &options, const Parameterization &map) {
  std::vector<std::string> causes;
  const std::vector<int> &collapsed = map.quality.collapsed_face_indices;
  if (!collapsed.empty()) {
    const Point3 &at = input.face[size_t(collapsed.front())].cP(0);
    std::ostringstream where;
    where << " (faces " << list_indices(collapsed) << "; the first at " << at[0] << ", " << at[1]
          << ", " << at[2] << ")";
    causes.push_back(plural(collapsed.size(), "face maps", "faces map") +
                     " to spots smaller than double precision resolves" + where.str() +
                     ": long thin parts shrink exponentially under a conformal map (shorten or "
                     "thicken them, or map them separately)");
  }
  int needles = 0;
  for (const MeshFace &face : mesh.face)
    needles += smallest_angle(face) < M_PI / 180;
  if (needles > 0)
    causes.push_back(plural(size_t(needles), "face has", "faces have") +
                     " an angle below 1 degree: remesh the surface (MeshLab: Filters > "
                     "Remeshing, Simplification and Reconstruction > Remeshing: Isotropic Explicit "
                     "Remeshing; Blender: Remesh modifier) and run again");
  if (map.genus >= 2 && options.form_pair[0] >= 0)
    causes.push_back("the chosen form pair may be nearly 0 / 0 on parts of this surface: use the "
                     "default generic pair (--forms -1,-1)");
  if (causes.empty())
    causes.push_back("the mesh may be too coarse near the branch points: refine it (MeshLab: "
                     "Filters > Remeshing, Simplification and Reconstruction > Subdivision "
                     "Surfaces: Midpoint; Blender: Subdivide) and run again");
  return join_phrases(causes);
}

// Faces whose written image is turned over (sphere_geometry.h).
int folded_face_count(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere) {
  int count = 0;
  for (const MeshFace &face : mesh.face)
    count += folded_image(sphere[size_t(index_of(mesh, face.cV(0)))],
                          sphere[size_t(index_of(mesh, face.cV(1)))],
                          sphere[size_t(index_of(mesh, face.cV(2)))]);
  return count;
}

// The map as it will be written, and how it got there.
struct WrittenSphere {
  std::vector<Eigen::Vector3d> sphere;
  MobiusCentering mobius;
  bool mobius_applied = false;
  int snapped_branch_points = 0, untangled_vertices = 0;
  Branching branching;
  int origin_vertex = -1; // genus 1
};

// From the meromorphic function's values to the map as written: centred (genus 0 and 1; genus >= 2
// comes centred with its pair), genus 1's half periods put on vertices, folds untangled, centred
// once more where vertices moved, and its branching measured.
void finish_on_sphere(const Mesh &mesh, const ParameterizeOptions &options,
                      const std::vector<double> &areas, const Genus1Map *torus_map, int euler,
                      std::vector<PlaneValue> values, WrittenSphere &out, const Progress &progress,
                      const std::function<void(const std::string &)> &lap) {
  if (options.mobius && euler >= 0) { // genus 0 and 1
    progress.report(0.7, "Moebius normalisation");
    out.mobius = center_on_sphere(values, areas);
    out.mobius_applied = true;
    lap("mobius");
  }
  if (torus_map) {
    // A piecewise-linear map branches only at vertices: the half periods go onto vertices,
    // decided on the centred map as it will be written (genus1_branch_placement.h).
    const Genus1Placement placed = place_half_period_branch_points(
        mesh, face_incidence(mesh), *torus_map, out.mobius.transformation, values);
    out.snapped_branch_points =
        int(std::count(placed.fold_free.begin(), placed.fold_free.end(), true));
    lap("branch_placement");
  }
  out.sphere.reserve(values.size());
  for (const PlaneValue &value : values)
    out.sphere.push_back(to_sphere(value));

  progress.report(0.8, "branch points and layers");
  // Everything below is measured on the map as written: vertex values, linear on each face.
  out.branching = analyse_branching(mesh, out.sphere, euler);
  out.untangled_vertices = untangle_folds(mesh, out.sphere, out.branching.branch_vertices);
  if (options.mobius && (out.untangled_vertices || out.snapped_branch_points)) {
    // The vertices moved above shift the centroid a little: centre once more.
    for (size_t v = 0; v < values.size(); ++v)
      if (!values[v].infinite && (to_sphere(values[v]) - out.sphere[v]).norm() > 1e-15)
        values[v] = to_plane_value(out.sphere[v]);
    const MobiusCentering again = center_on_sphere(values, areas);
    out.mobius.transformation = again.transformation.after(out.mobius.transformation);
    out.mobius.centroid_after = again.centroid_after;
    out.mobius.steps += again.steps;
    for (size_t v = 0; v < values.size(); ++v)
      out.sphere[v] = to_sphere(values[v]);
  }
  if (out.untangled_vertices || options.mobius)
    out.branching = analyse_branching(mesh, out.sphere, euler);
}

void adopt(WrittenSphere &&written, Parameterization &out, Branching &branching) {
  out.sphere = std::move(written.sphere);
  out.mobius = written.mobius;
  out.mobius_applied = written.mobius_applied;
  out.snapped_branch_points = written.snapped_branch_points;
  out.untangled_vertices = written.untangled_vertices;
  if (written.origin_vertex >= 0) out.origin_vertex = written.origin_vertex;
  branching = std::move(written.branching);
}
} // namespace

Parameterization parameterize(const Mesh &input, const ParameterizeOptions &options,
                              const Progress &progress, const Validation *validated) {
  // The mesh is validated once: by the caller, or by compute_holomorphic_forms below.
  if (!(options.layer_gap >= 0 && options.layer_gap <= 1e6))
    throw ArgumentError("the layer gap must be a number from 0 to 1e6");
  // Everything is computed at unit scale (unit_scale.h); positions reported are the input's.
  Mesh mesh;
  copy_at_unit_scale(input, unit_scale_of(input), mesh);
  const std::vector<double> areas = vertex_areas(mesh); // the weights of the Moebius centring

  Parameterization out;
  auto clock = std::chrono::steady_clock::now();
  auto lap = [&](const std::string &stage) {
    const auto now = std::chrono::steady_clock::now();
    out.timings_ms.push_back(
        {stage, std::chrono::duration<double, std::milli>(now - clock).count()});
    clock = now;
  };

  const HolomorphicForms forms =
      compute_holomorphic_forms(mesh, options.solver, progress.range(0.0, 0.6), validated);
  for (const auto &timing : forms.timings_ms)
    out.timings_ms.push_back(timing);
  clock = std::chrono::steady_clock::now();
  out.genus = forms.genus;
  out.euler = 2 - 2 * out.genus;
  out.non_holomorphicity_mean = forms.non_holomorphicity_mean;
  out.notes = forms.notes;

  progress.report(0.6, "meromorphic function");
  std::vector<PlaneValue> values;
  std::vector<int> origins; // genus 1: where the double pole may go, best first

  if (out.genus == 0) {
    // The plain cotangent map is the most conformal; if it folds (negative weights on meshes with
    // many obtuse triangles), the map with strictly positive weights cannot.
    // Weights are raised only near folds (two rings), round by round; all of them at the end.
    auto solve = [&](int pole_face) {
      std::vector<char> raise(forms.edges.edge_count(), 0);
      Genus0Map attempt =
          genus0_map(mesh, forms.edges, forms.weights, options.solver, pole_face, raise);
      for (int round = 0; round < 4 && !attempt.folded_faces.empty(); ++round) {
        std::set<int> near;
        for (int f : attempt.folded_faces)
          for (int k = 0; k < 3; ++k)
            near.insert(index_of(mesh, mesh.face[f].cV(k)));
        for (int ring = 0; ring < 2; ++ring) {
          std::set<int> grown = near;
          for (int e = 0; e < forms.edges.edge_count(); ++e)
            if (near.count(forms.edges.vertices[e][0]) || near.count(forms.edges.vertices[e][1])) {
              grown.insert(forms.edges.vertices[e][0]);
              grown.insert(forms.edges.vertices[e][1]);
            }
          near = grown;
        }
        for (int e = 0; e < forms.edges.edge_count(); ++e)
          if (near.count(forms.edges.vertices[e][0]) && near.count(forms.edges.vertices[e][1]))
            raise[e] = 1;
        attempt = genus0_map(mesh, forms.edges, forms.weights, options.solver, pole_face, raise);
      }
      if (!attempt.folded_faces.empty())
        attempt = genus0_map(mesh, forms.edges, forms.weights, options.solver, pole_face, {});
      return attempt;
    };
    // The pinned-pole map, its shear removed and its pole region solved again
    // (genus0_correction.h).
    auto solve_and_correct = [&](int pole_face) {
      Genus0Map map = solve(pole_face);
      map.values = correct_genus0_map(mesh, forms.edges, map.weights, options.solver,
                                      map.puncture_face, map.values)
                       .values;
      return map;
    };
    Genus0Map map = solve_and_correct(options.puncture_face);
    if (options.puncture_face < 0) {
      // Parts far from the pole crowd into a tiny spot, where rounding can fold or collapse
      // faces. Then solve again with the pole at the face that the centred map puts on the north
      // pole: the new map is nearly centred, so nothing is crowded.
      std::vector<PlaneValue> centred = map.values;
      const bool centred_ok = center_on_sphere(centred, areas).centroid_after.norm() < 1e-9;
      const int collapsed = collapsed_faces(mesh, centred);
      if (!centred_ok || collapsed > 0 || !folded_plane_faces(mesh, centred).empty()) {
        // Any face the centred map puts near the north pole will do; the best-shaped of those
        // models the pole most accurately.
        int pole_face = -1;
        double best_angle = -1;
        for (size_t f = 0; f < mesh.face.size(); ++f) {
          bool near_north = true;
          for (int k = 0; k < 3; ++k)
            near_north &= to_sphere(centred[index_of(mesh, mesh.face[f].cV(k))]).z() > 0.9;
          if (!near_north) continue;
          const double angle = smallest_angle(mesh.face[f]);
          if (angle > best_angle) {
            best_angle = angle;
            pole_face = int(f);
          }
        }
        if (pole_face >= 0) {
          // Where long thin parts shrink below what doubles resolve, a pole in the wrong place
          // loses more of them: keep the first solution if the second collapses more faces.
          Genus0Map again = solve_and_correct(pole_face);
          std::vector<PlaneValue> centred_again = again.values;
          center_on_sphere(centred_again, areas);
          if (collapsed_faces(mesh, centred_again) <= collapsed) map = std::move(again);
        }
      }
    }
    values = map.values;
    out.puncture_face = map.puncture_face;
    out.raised_weights = map.raised_weights;
    out.method = "genus 0: harmonic map with a simple pole (strictly positive weights), inverse "
                 "stereographic projection";
  } else if (out.genus == 1) {
    out.modulus = forms.modulus;
    out.riemann_matrix = forms.riemann_matrix;
    if (options.origin_vertex >= 0)
      origins = {options.origin_vertex};
    else
      origins = genus1_origin_candidates(mesh, forms.edges, forms.normalized[0],
                                         WeierstrassP(Complex(1, 0), forms.riemann_matrix(0, 0)));
    out.method = "genus 1: Weierstrass P-function of the flat coordinate";
  } else {
    out.riemann_matrix = forms.riemann_matrix;
    out.form_pair = options.form_pair;
    const auto [i, j] = options.form_pair;
    std::vector<FormPair> pairs;
    if (i < 0 && j < 0) {
      pairs = generic_form_pairs(out.genus);
    } else {
      if (i < 0 || j < 0 || i >= out.genus || j >= out.genus || i == j)
        throw ArgumentError("the form pair must be two different indices between 0 and " +
                            std::to_string(out.genus - 1) + " (or -1, -1 for the generic pair)");
      FormPair pair{Eigen::VectorXcd::Zero(out.genus), Eigen::VectorXcd::Zero(out.genus)};
      pair.first[i] = pair.second[j] = 1.0;
      pairs.push_back(pair);
    }
    // A pair is generic when the measured degree is 2g - 2 and Riemann-Hurwitz holds. Where a
    // mesh is too coarse to resolve a pair's map (its image crowds where both forms live on the
    // same handle), the next pair of the fixed list is tried; the best one is kept.
    struct Attempt {
      bool generic;
      int deficit; // |chi - (2 d - ramification)|
      std::vector<PlaneValue> values;
      MobiusCentering centring;
      int snapped;
      int crowded = 0; // faces whose image spans more than a chord of 1 (a quarter of the sphere)
    };
    std::optional<Attempt> best;
    for (size_t attempt = 0; attempt < pairs.size(); ++attempt) {
      progress.report(0.6 + 0.1 * double(attempt) / double(pairs.size()), "meromorphic function");
      Eigen::VectorXcd omega1 = Eigen::VectorXcd::Zero(forms.edges.edge_count());
      Eigen::VectorXcd omega2 = omega1;
      for (int k = 0; k < out.genus; ++k) {
        omega1 += pairs[attempt].first[k] * forms.normalized[k];
        omega2 += pairs[attempt].second[k] * forms.normalized[k];
      }
      const Eigen::VectorXcd numerator = omega1 + omega2, denominator = omega1 - omega2;
      Attempt result{false, 0, form_ratio_map(mesh, forms.edges, numerator, denominator), {}, 0};
      if (options.mobius) result.centring = center_on_sphere(result.values, areas);
      for (int pass = 0; pass < 4; ++pass) {
        const int repaired =
            snap_branch_points(mesh, forms.edges, {&numerator, &denominator}, result.values);
        result.snapped += repaired;
        if (!repaired) break;
      }
      std::vector<Eigen::Vector3d> sphere;
      for (const PlaneValue &value : result.values)
        sphere.push_back(to_sphere(value));
      const Branching measured = analyse_branching(mesh, sphere, out.euler);
      result.generic = measured.riemann_hurwitz_ok && measured.degree == 2 * out.genus - 2;
      result.deficit = std::abs(out.euler - (2 * measured.degree - measured.ramification));
      for (const MeshFace &face : mesh.face) {
        const Eigen::Vector3d &a = sphere[index_of(mesh, face.cV(0))],
                              &b = sphere[index_of(mesh, face.cV(1))],
                              &c = sphere[index_of(mesh, face.cV(2))];
        result.crowded += std::max({(a - b).norm(), (b - c).norm(), (c - a).norm()}) > 1.0;
      }
      auto rank = [](const Attempt &a) {
        return std::make_tuple(!a.generic, a.deficit, a.crowded);
      };
      if (!best || rank(result) < rank(*best)) {
        best = std::move(result);
        out.form_coefficients = pairs[attempt];
      }
      out.pair_attempts = int(attempt) + 1;
      // Where a zero and a pole of the ratio fall within a face or two, a face's image spans a
      // good part of the sphere (and its texture with it); another generic pair puts them
      // elsewhere. For genus 2 every generic pair gives the same map up to a Moebius
      // transformation: no other pair helps there. Three pairs at most for that: on surfaces
      // whose handles crowd everywhere, every pair does.
      if (best->generic && (best->crowded == 0 || out.genus == 2 || attempt >= 2)) break;
    }
    values = std::move(best->values);
    out.mobius = best->centring;
    out.mobius_applied = options.mobius;
    out.snapped_branch_points = best->snapped;
    out.method = "genus " + std::to_string(out.genus) +
                 ": ratio (omega1 + omega2) / (omega1 - omega2), omega1 = sum a_k psi_k, "
                 "omega2 = sum b_k psi_k of the normalized holomorphic 1-forms psi_k (a_k, b_k: "
                 "form_coefficients)";
  }
  lap("meromorphic");

  Branching branching;
  if (out.genus != 1) {
    WrittenSphere written{{}, out.mobius, out.mobius_applied, out.snapped_branch_points, 0, {}};
    finish_on_sphere(mesh, options, areas, nullptr, out.euler, values, written, progress, lap);
    adopt(std::move(written), out, branching);
  } else {
    // Each origin puts the half periods, where P branches too, elsewhere: where the best-scored
    // one leaves a fold or a missed branch point, the next is tried (four in all at most). The
    // first valid map is kept, else the first.
    std::optional<WrittenSphere> first;
    for (size_t k = 0; k < std::min<size_t>(4, origins.size()); ++k) {
      const Genus1Map map = genus1_map(mesh, forms.edges, forms.normalized[0], Complex(1, 0),
                                       forms.riemann_matrix(0, 0), origins[k]);
      WrittenSphere written{{}, {}, false, 0, 0, {}};
      finish_on_sphere(mesh, options, areas, &map, out.euler, map.values, written, progress, lap);
      written.origin_vertex = map.origin_vertex;
      out.origin_attempts = int(k) + 1;
      const bool valid = written.branching.degree == 2 && written.branching.riemann_hurwitz_ok &&
                         folded_face_count(mesh, written.sphere) == 0;
      if (valid || k == 0) first = std::move(written);
      if (valid) break;
    }
    adopt(std::move(*first), out, branching);
  }
  out.degree = branching.degree;
  out.area_over_4pi = branching.area_over_4pi;
  out.ramification = branching.ramification;
  out.riemann_hurwitz_ok = branching.riemann_hurwitz_ok;
  out.branch_flag.assign(mesh.vert.size(), 0);
  for (int v : branching.branch_vertices) {
    const Point3 &p = input.vert[v].cP();
    out.branch_points.push_back(
        {v, Eigen::Vector3d(p[0], p[1], p[2]), out.sphere[v], branching.local_degree[v]});
    out.branch_flag[v] = branching.local_degree[v];
  }
  out.sheets = label_sheets(mesh, forms.edges, out.sphere, branching.branch_vertices, out.degree);
  out.layered = out.sphere;
  for (size_t v = 0; v < out.layered.size(); ++v)
    out.layered[v] *= 1.0 + options.layer_gap * out.sheets.vertex_layer[v];
  lap("branching");

  progress.report(0.9, "texture coordinates and distortion");
  out.uv = texture_coordinates(mesh, out.sphere, options.uv);
  out.quality = measure_map_quality(mesh, out.sphere, branching.branch_vertices);
  out.invalid = invalid_reasons(options, out);
  out.valid = out.invalid.empty();
  if (!out.valid) out.advice = invalid_map_advice(input, mesh, options, out);
  lap("texture_and_quality");
  progress.report(1.0, "done");
  return out;
}

} // namespace meromorph
