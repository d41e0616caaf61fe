// Per-vertex values of one surface read at the matched points of another (`meromorph transfer`).
//
// In:  the target's per-vertex values (a PLY file's scalar properties: colours, texture
//      coordinates, quality, labels), its triangles, and where each source vertex lies on it
//      (surface_match.h: the target triangle and the weights of its second and third corners).
// Out: the values at the source's vertices, with the same names and types: real values
//      interpolated by the weights; one-byte integers (colours) interpolated, rounded and kept in
//      0..255; other integers (labels, ids) taken from the corner with the largest weight, never
//      mixed. A vertex that was not matched gets 0.
#pragma once

#include <array>
#include <vector>

#include "match/surface_match.h"
#include "mesh/mesh_from_arrays.h"

namespace meromorph {

std::vector<VertexValues> carried_values(const std::vector<VertexValues> &target_values,
                                         const std::vector<std::array<int, 3>> &target_triangles,
                                         const MatchedPoints &points);

} // namespace meromorph
