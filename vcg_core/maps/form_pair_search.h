// Genus >= 2: the meromorphic function as a ratio of two holomorphic forms, over the pairs tried.
//
// In:  a closed mesh of genus g >= 2 (unit scale), its holomorphic forms (holomorphic_pipeline.h),
//      the pair asked for (-1, -1: the fixed list of generic pairs, form_pairs.h), whether to
//      centre, the surface area per vertex (the centring's weights), progress.
// Out: for each pair, f = (omega1 + omega2) / (omega1 - omega2) per vertex (form_ratio_map.h),
//      centred and its crowded faces counted (an image chord above 1); then its critical points
//      snapped onto vertices (branch_snapping.h, up to four passes) and ranked by whether it is
//      generic (degree 2g - 2 and Riemann-Hurwitz; where it is not, the map with its slivers'
//      folds untangled, fold_untangling.h, if that one is), its Riemann-Hurwitz deficit and its
//      crowded faces; the best is kept, with its branching as measured for the ranking. Genus 2:
//      the next pair only where the best is not generic (every generic pair gives the same map up
//      to a Moebius transformation). Genus 3 and up: up to three pairs solved (the first whose map
//      does not crowd snapped and kept at once if generic), then snapped from the least crowded
//      until one is generic; further pairs one at a time while none is. Where the first pair's
//      guessed map crowds (form_ratio_map.h's guessed_crowding, before any solve), the pair
//      whose guess crowds least goes first. A map whose image area is not 2g - 2 spheres
//      before snapping (a sheet lost where zeros and poles crowd) is snapped only where no
//      other pair's map is generic.
//      Throws ArgumentError for a pair that is not two different form indices.
#pragma once

#include <array>
#include <vector>

#include "common/progress.h"
#include "forms/holomorphic_pipeline.h"
#include "maps/form_pairs.h"
#include "mesh/prepared_mesh.h"
#include "sphere/branch_points.h"
#include "sphere/mobius_centering.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {

struct PairSearch {
  std::vector<PlaneValue> values;
  MobiusCentering centring;
  int snapped_branch_points = 0;
  int untangled_vertices = 0; // folds of slivers untangled in the search (fold_untangling.h)
  Branching branching;        // of `values`, as the ranking measured it
  FormPair coefficients;
  int attempts = 0;      // pairs whose map was solved
  int snapped_pairs = 0; // pairs whose map's critical points were snapped
};

PairSearch search_form_pairs(const PreparedMesh &prepared, const HolomorphicForms &forms,
                             std::array<int, 2> form_pair, bool mobius, const Progress &progress);

} // namespace meromorph
