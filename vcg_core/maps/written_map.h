// From the meromorphic function's values to the map as it will be written.
//
// In:  the mesh (unit scale), whether to centre, the surface area per vertex (the centring's
//      weights), the Euler characteristic, progress and the stage clock; `finish_on_sphere`: the
//      values in the extended plane, and for genus 1 the P-function map (genus1_map.h); genus >= 2
//      values come centred with their pair (form_pair_search.h). `written_genus1_map`: the forms
//      and the vertices where the double pole may go, best first.
// Out: `WrittenSphere`: the unit-sphere position per vertex, centred (genus 0 and 1), genus 1's
//      half periods put on vertices (genus1_branch_placement.h), folds untangled
//      (fold_untangling.h), centred once more where vertices moved, and its branching measured
//      (branch_points.h); what was done on the way. `written_genus1_map` tries the origins in
//      turn (four at most: each puts the half periods, where P branches too, elsewhere) and keeps
//      the first valid map (degree 2, Riemann-Hurwitz, no folded face), else the first.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "common/progress.h"
#include "common/stage_clock.h"
#include "forms/holomorphic_pipeline.h"
#include "maps/genus1_map.h"
#include "mesh/prepared_mesh.h"
#include "sphere/branch_points.h"
#include "sphere/mobius_centering.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {

struct WrittenSphere {
  std::vector<Eigen::Vector3d> sphere;
  MobiusCentering mobius;
  bool mobius_applied = false;
  // (`out`'s counts as given are kept and added to: genus >= 2's pair search snaps and may
  // untangle before.)
  int snapped_branch_points = 0, untangled_vertices = 0;
  Branching branching;
  int origin_vertex = -1, origin_attempts = 0; // genus 1
  std::vector<Complex> flat;                   // genus 1: z per vertex (genus1_map.h)
};

// `measured`: the branching of `values` as given, where the caller measured it (genus >= 2; used
// only where the values are neither centred nor placed here), or null. `centred`: `values`
// centred, where the caller centred them already (genus 0), or null.
void finish_on_sphere(const PreparedMesh &prepared, bool mobius, const Genus1Map *torus_map,
                      int euler, std::vector<PlaneValue> values, const Branching *measured,
                      const CentredValues *centred, WrittenSphere &out, const Progress &progress,
                      StageClock &clock);

WrittenSphere written_genus1_map(const PreparedMesh &prepared, const HolomorphicForms &forms,
                                 const std::vector<int> &origins, bool mobius,
                                 const Progress &progress, StageClock &clock);

} // namespace meromorph
