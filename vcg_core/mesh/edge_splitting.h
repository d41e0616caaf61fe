// Faces cut at the midpoints of chosen edges, keeping the surface (and its numbering) as it was.
//
// In:  plain arrays of a triangle mesh (mesh_from_arrays.h) and the edges to cut, as vertex pairs
//      (either order; an edge that is not in the mesh is ignored).
// Out: the same arrays with a vertex at the midpoint of every chosen edge, appended after the
//      vertices there were, in the order the edges are first met face by face; every face on a
//      cut edge is cut with it, so the result has no T-junction: a face with one cut edge into
//      two, with two into three (the quadrilateral left by its shorter diagonal), with three into
//      four. A cut face keeps its slot with its piece at its first corner; its other pieces are
//      appended, and `face_source` names, per face of the result, the face it was cut from.
//      `split_long_edges` cuts every
//      edge longer than `max_length`, again and again until none is (long thin faces become
//      many well-shaped ones; `face_source` names the input's faces); none when that would make
//      more than `face_budget` faces.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "mesh/mesh_from_arrays.h"

namespace meromorph {

struct SplitEdges {
  MeshArrays arrays;
  std::vector<int> face_source;
};

SplitEdges split_edges(const MeshArrays &arrays, const std::vector<std::array<int, 2>> &edges);

// `refined` with `sides` (of its own arrays) cut too; its face sources stay the first mesh's.
void cut_sides(SplitEdges &refined, const std::vector<std::array<int, 2>> &sides);

std::optional<SplitEdges> split_long_edges(const MeshArrays &arrays, double max_length,
                                           size_t face_budget);

} // namespace meromorph
