#include "maps/genus0_best_map.h"

#include "common/parallel_for.h"
#include "forms/intrinsic_delaunay.h"
#include "maps/fold_untangling.h"
#include "maps/genus0_correction.h"
#include "maps/genus0_map.h"
#include "maps/south_cap_prediction.h"
#include "mesh/face_vectors.h"
#include "sphere/map_quality.h"
#include "sphere/mobius_centering.h"

namespace meromorph {
namespace {

// How a centred map compares with another, as it will be written (sliver folds untangled:
// fold_untangling.h): faces collapsed below double resolution first, then faces turned over, then
// the mean angle error (measured only where two maps are compared).
struct CentredQuality {
  int collapsed = 0, folded = 0;
  double angle_error = -1; // not measured yet
  bool better_than(const CentredQuality &other) const {
    if (collapsed != other.collapsed) return collapsed < other.collapsed;
    if (folded != other.folded) return folded < other.folded;
    return angle_error < other.angle_error;
  }
};

std::vector<Eigen::Vector3d> as_written(const PreparedMesh &prepared,
                                        const std::vector<PlaneValue> &centred) {
  std::vector<Eigen::Vector3d> sphere(centred.size());
  parallel_for(centred.size(), [&](size_t v) { sphere[v] = to_sphere(centred[v]); });
  untangle_folds(prepared, sphere, {});
  return sphere;
}

CentredQuality quality_of(const PreparedMesh &prepared,
                          const std::vector<Eigen::Vector3d> &written) {
  const auto &corners = prepared.incidence.corners;
  using Counts = Eigen::Vector2i; // folded, collapsed
  const Counts counts =
      chunked_sum(corners.size(), Counts::Zero().eval(), [&](size_t begin, size_t end) {
        Counts part = Counts::Zero();
        for (size_t f = begin; f < end; ++f) {
          const std::array<int, 3> &c = corners[f];
          const Eigen::Vector3d &a = written[size_t(c[0])], &b = written[size_t(c[1])],
                                &d = written[size_t(c[2])];
          part[0] += folded_as_measured(a, b, d);
          part[1] += collapsed_image(a, b, d);
        }
        return part;
      });
  return {counts[1], counts[0]};
}

// The pinned-pole map of `pole_face` (-1: the default face). With `repair_folds`, where it folds
// (negative weights on meshes with many obtuse triangles), weights are raised to positive ones
// near the folds (two rings), round by round; all of them at the end: with strictly positive
// weights it cannot fold.
Genus0Map unfolded_map(const PreparedMesh &prepared, SolverKind solver, int pole_face,
                       bool repair_folds) {
  if (pole_face < 0) pole_face = default_pole_face(prepared);
  // With CHOLMOD, one factorization serves both steps where the south-pole step's cap is
  // predicted well enough (south_cap_prediction.h).
  std::vector<char> cap;
  if (solver == SolverKind::cholmod) {
    int raised = 0;
    try { // a prediction only saves a factorization: none where it cannot be made
      cap =
          predicted_south_cap(prepared, positive_weights(prepared.weights, {}, raised), pole_face);
    } catch (const std::exception &) {
      cap.clear();
    }
  }
  std::vector<char> raise(prepared.edges.edge_count(), 0);
  Genus0Map attempt = genus0_map(prepared, solver, pole_face, raise, cap);
  if (!repair_folds) return attempt;
  const std::vector<int> order = attempt.elimination_order; // the same for the same pole
  for (int round = 0; round < 4 && !attempt.folded_faces.empty(); ++round) {
    // The weights change only there: solve again within a few rings of them first, the rest of
    // the map kept; the whole map again where that still folds.
    std::vector<char> region;
    region_around_folds(prepared, attempt.folded_faces, raise, region);
    Genus0Map local = genus0_map_again_in(prepared, attempt, raise, region);
    if (local.folded_faces.empty()) {
      // The factor stays good for the south-pole step, which repairs folds the same way.
      local.cap_last = std::move(attempt.cap_last);
      attempt = std::move(local);
    } else if (std::optional<Genus0Map> whole = genus0_map_reweighted(prepared, attempt, raise)) {
      whole->cap_last = std::move(attempt.cap_last);
      attempt = std::move(*whole);
    } else {
      attempt.cap_last = {}; // one factor held at a time
      attempt = genus0_map(prepared, solver, pole_face, raise, cap, order);
    }
  }
  if (!attempt.folded_faces.empty()) {
    attempt.cap_last = {};
    attempt = genus0_map(prepared, solver, pole_face, {}, cap, order);
  }
  return attempt;
}

// The pinned-pole map, its shear removed and its pole region solved again
// (genus0_correction.h); `finished`: whether both correction steps were taken.
Genus0Map corrected_map(const PreparedMesh &prepared, SolverKind solver, int pole_face,
                        bool repair_folds, bool &finished) {
  Genus0Map map = unfolded_map(prepared, solver, pole_face, repair_folds);
  const Genus0Correction correction =
      correct_genus0_map(prepared, map.weights, solver, map.pole_face, map.values,
                         map.elimination_order, map.cap_last);
  map.values = correction.values;
  finished = correction.steps_taken == 2;
  map.cap_last = {};
  return map;
}

// Of the faces the centred map puts near the north pole, the best-shaped (it models the pole
// most accurately); -1 where there is none.
int face_at_north_pole(const PreparedMesh &prepared, const std::vector<PlaneValue> &centred) {
  return best_shaped_face_among(prepared.mesh, [&](size_t f) {
    for (int k = 0; k < 3; ++k)
      if (!(to_sphere(centred[prepared.incidence.corners[f][k]]).z() > 0.9)) return false;
    return true;
  });
}

// The map solved with the weights of `solving` (its edges and weights; faces, geometry and
// areas those of `prepared`), centred and judged on the mesh's faces as it will be written.
struct Candidate {
  Genus0Map map;
  CentredValues centred;
  std::vector<Eigen::Vector3d> written; // as_written(centred)
  CentredQuality quality;
};

Candidate centred_candidate(const PreparedMesh &prepared, Genus0Map map) {
  CentredValues centred{map.values, {}};
  centred.centring = center_on_sphere(centred.values, prepared.vertex_areas);
  std::vector<Eigen::Vector3d> written = as_written(prepared, centred.values);
  const CentredQuality quality = quality_of(prepared, written);
  return {std::move(map), std::move(centred), std::move(written), quality};
}

void measure_angle_error(const PreparedMesh &prepared, Candidate &candidate) {
  if (candidate.quality.angle_error < 0)
    candidate.quality.angle_error = mean_angle_error_degrees(prepared.mesh, candidate.written);
}

Candidate solved_on(const PreparedMesh &solving, const PreparedMesh &prepared, SolverKind solver,
                    int pole_face_asked, bool repair_folds) {
  bool finished = false;
  Candidate first = centred_candidate(
      prepared, corrected_map(solving, solver, pole_face_asked, repair_folds, finished));
  if (pole_face_asked >= 0) return first;
  // Parts far from the pole crowd into a tiny spot, where rounding can fold or collapse faces;
  // and a pole among needles can keep the correction from finishing. Then solve again with the
  // pole at the face that the centred map puts on the north pole: the new map is nearly centred,
  // so nothing is crowded. It is kept only where it is the better one (a second pole can lose
  // more of the long thin parts, or sit among needles).
  const bool centred_ok = first.centred.centring.centroid_after.norm() < 1e-9;
  const CentredQuality &quality = first.quality;
  if (centred_ok && finished && quality.collapsed == 0 && quality.folded == 0) return first;
  const int pole_face = face_at_north_pole(prepared, first.centred.values);
  if (pole_face < 0) return first;
  Candidate again = centred_candidate(
      prepared, corrected_map(solving, solver, pole_face, repair_folds, finished));
  measure_angle_error(prepared, first);
  measure_angle_error(prepared, again);
  return again.quality.better_than(first.quality) ? std::move(again) : std::move(first);
}

} // namespace

Genus0Result best_genus0_map(const PreparedMesh &prepared, SolverKind solver, int pole_face_asked) {
  // The intrinsic Delaunay triangulation's weights are non-negative where the mesh's cotangent
  // weights are negative (obtuse corners, needles), and its map is the more conformal there:
  // tried first. Where its map folds or collapses faces of the mesh (as written, after
  // untangling), the mesh's own weights, raised near folds, are tried, and the better map kept.
  Candidate best =
      solved_on(prepared_on_intrinsic_delaunay(prepared), prepared, solver, pole_face_asked, false);
  bool intrinsic = true;
  if (best.quality.folded > 0 || best.quality.collapsed > 0) {
    Candidate raised = solved_on(prepared, prepared, solver, pole_face_asked, true);
    measure_angle_error(prepared, best);
    measure_angle_error(prepared, raised);
    if (raised.quality.better_than(best.quality)) {
      best = std::move(raised);
      intrinsic = false;
    }
  }
  return {best.map.values, best.map.pole_face, best.map.raised_weights, intrinsic,
          std::move(best.centred)};
}

} // namespace meromorph
