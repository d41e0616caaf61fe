// Parts as CAD programs export them (STL): planar faces cut into long thin triangles between
// their outline and their holes, walls as strips of two triangles per segment.
//
// In:  the number of holes g, the segments around each circle, the part's thickness.
// Out: a closed, connected, outward oriented mesh of genus g:
//      g = 0: a cylinder of radius 1 and height `thickness`, each cap fanned from one rim vertex
//      (corners of 180 / segments degrees there), the wall a strip;
//      g >= 1: a plate of g unit squares in a row, each with a round hole of radius 0.3 at its
//      centre; its top and bottom faces cut from the squares' corners to the holes' circles (fans
//      of long thin triangles), its outer walls and the holes' walls strips of two triangles per
//      side or segment (on a thin plate, corners down to atan(thickness) at the outer walls).
#pragma once

#include "mesh/mesh.h"

namespace meromorph {

void make_cad_part(Mesh &mesh, int holes, int segments, double thickness);

} // namespace meromorph
