// Genus 0: where the south-pole step's cap will lie, before the pinned-pole map is solved.
//
// In:  a closed genus-0 prepared mesh, positive edge weights, the puncture face.
// Out: one flag per vertex, set on the south cap (genus0_correction.h: the share of vertices
//      nearest the median value) of a coarse pinned-pole map; empty where the mesh is too small
//      to predict from or too small to coarsen (at most 4096 vertices: predicting there costs
//      the factorization it saves, 2 ms of a 27 ms run at 2.3k vertices). The coarse map: vertices
//      gathered into aggregates (a vertex with its neighbours while none of them is taken, the rest
//      joined to a neighbour's), repeated until a few thousand remain; the aggregates' graph
//      Laplacian (the weights between two aggregates summed); the aggregates at the puncture left
//      out and those around them pinned at 1 / w, w their centroid in the puncture face's frame.
//      Aggregates of about equal vertex counts scale every coarse weight about alike, which a
//      harmonic map does not see. Why: a factorization that eliminates the cap last serves both
//      genus-0 steps, the south-pole step solving with the factor's leading block
//      (leading_block_solve.h).
#pragma once

#include <vector>

#include "mesh/prepared_mesh.h"

namespace meromorph {

std::vector<char> predicted_south_cap(const PreparedMesh &prepared,
                                      const std::vector<double> &positive_weights, int pole_face);

} // namespace meromorph
