// Safe repairs: the ones that do not move a vertex or change the shape.
//
// In:  a mesh (any state validation accepts or reports).
// Out: the same mesh with exact duplicate vertices on the edges of holes merged (a seam; those the
//      surface keeps apart stay), faces that repeat a vertex removed (zero-area faces stay:
//      removing one would open a hole), doubled faces (on the same three vertices as an earlier
//      one, either way round) removed, unreferenced vertices removed and faces oriented
//      consistently (outward on a closed surface), then compacted (indices change). Returns one
//      sentence per repair made, in the user's words, for the report; empty when nothing needed
//      repair. Holes, non-manifold edges and several components are not repaired: they change the
//      shape.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace meromorph {

std::vector<std::string> repair_mesh(Mesh &mesh);

} // namespace meromorph
