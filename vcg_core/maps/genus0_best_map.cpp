#include "maps/genus0_best_map.h"

#include "common/parallel_for.h"
#include "maps/genus0_correction.h"
#include "maps/genus0_map.h"
#include "maps/south_cap_prediction.h"
#include "mesh/face_vectors.h"
#include "sphere/mobius_centering.h"

namespace meromorph {
namespace {

// Faces whose image is below double resolution (sphere_geometry.h).
int collapsed_faces(const FaceIncidence &in, const std::vector<PlaneValue> &values) {
  return chunked_sum(in.corners.size(), 0, [&](size_t begin, size_t end) {
    int count = 0;
    for (size_t f = begin; f < end; ++f) {
      const std::array<int, 3> &c = in.corners[f];
      count += collapsed_image(to_sphere(values[size_t(c[0])]), to_sphere(values[size_t(c[1])]),
                               to_sphere(values[size_t(c[2])]));
    }
    return count;
  });
}

// The pinned-pole map of `pole_face` (-1: the default face). The plain cotangent map is the most
// conformal; if it folds (negative weights on meshes with many obtuse triangles), the map with
// strictly positive weights cannot. Weights are raised only near folds (two rings), round by
// round; all of them at the end.
Genus0Map unfolded_map(const PreparedMesh &prepared, SolverKind solver, int pole_face) {
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
// (genus0_correction.h).
Genus0Map corrected_map(const PreparedMesh &prepared, SolverKind solver, int pole_face) {
  Genus0Map map = unfolded_map(prepared, solver, pole_face);
  map.values = correct_genus0_map(prepared, map.weights, solver, map.pole_face, map.values,
                                  map.elimination_order, map.cap_last)
                   .values;
  map.cap_last = {};
  return map;
}

// Of the faces the centred map puts near the north pole, the best-shaped (it models the pole
// most accurately); -1 where there is none.
int face_at_north_pole(const PreparedMesh &prepared, const std::vector<PlaneValue> &centred) {
  int pole_face = -1;
  double best_angle = -1;
  for (size_t f = 0; f < prepared.mesh.face.size(); ++f) {
    bool near_north = true;
    for (int k = 0; k < 3; ++k)
      near_north &= to_sphere(centred[prepared.incidence.corners[f][k]]).z() > 0.9;
    if (!near_north) continue;
    const double angle = smallest_angle(prepared.mesh.face[f]);
    if (angle > best_angle) {
      best_angle = angle;
      pole_face = int(f);
    }
  }
  return pole_face;
}

} // namespace

Genus0Result best_genus0_map(const PreparedMesh &prepared, SolverKind solver, int pole_face_asked) {
  const std::vector<double> &areas = prepared.vertex_areas;
  Genus0Map map = corrected_map(prepared, solver, pole_face_asked);
  std::optional<CentredValues> centred_map;
  if (pole_face_asked < 0) {
    // Parts far from the pole crowd into a tiny spot, where rounding can fold or collapse
    // faces. Then solve again with the pole at the face that the centred map puts on the north
    // pole: the new map is nearly centred, so nothing is crowded.
    centred_map = CentredValues{map.values, {}};
    std::vector<PlaneValue> &centred = centred_map->values;
    centred_map->centring = center_on_sphere(centred, areas);
    const bool centred_ok = centred_map->centring.centroid_after.norm() < 1e-9;
    const int collapsed = collapsed_faces(prepared.incidence, centred);
    const int pole_face =
        !centred_ok || collapsed > 0 || !folded_plane_faces(prepared.incidence, centred).empty()
            ? face_at_north_pole(prepared, centred)
            : -1;
    if (pole_face >= 0) {
      // Where long thin parts shrink below what doubles resolve, a pole in the wrong place
      // loses more of them: keep the first solution if the second collapses more faces.
      Genus0Map again = corrected_map(prepared, solver, pole_face);
      CentredValues centred_again{again.values, {}};
      centred_again.centring = center_on_sphere(centred_again.values, areas);
      if (collapsed_faces(prepared.incidence, centred_again.values) <= collapsed) {
        map = std::move(again);
        centred_map = std::move(centred_again);
      }
    }
  }
  return {map.values, map.pole_face, map.raised_weights, std::move(centred_map)};
}

} // namespace meromorph
