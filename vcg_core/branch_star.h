// The one-ring of a vertex in order, as a branch point's star needs it.
//
// In:  face incidence and a vertex.
// Out: the one-ring counter-clockwise seen from outside (faces (vertex, ring[j], ring[j + 1])),
//      starting at the first face's neighbour; empty if it is not a simple cycle.
#pragma once

#include <vector>

#include "mesh_edges.h"

namespace meromorph {

std::vector<int> ordered_ring(const FaceIncidence &in, int vertex);

} // namespace meromorph
