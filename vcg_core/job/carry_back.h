// A map computed on a work mesh (the input with some vertices merged and some faces changed or left
// out) carried back to the mesh it came from.
//
// In:  `whole`, the mesh the work mesh came from; how many vertices the work mesh has; per whole
//      vertex its work vertex (-1: none), per whole face its work face with the same corners in
//      the same order (-1: none); the options; the map on the work mesh (when non-manifold spots
//      were split, its per-vertex arrays are the split mesh's: the work vertices, then copies).
// Out: the map on `whole`: a vertex takes the values of its work vertex, its branch flag when it is
//      at the same position (one with none: the sphere's north pole, layer 0, no branch); a face
//      with a work face takes its texture coordinates and layer, any other face its corners'
//      texture coordinates (unwrapped across the seam) and its first corner's layer; the split's
//      copies follow the whole vertices; branch points, holes, the origin and the pole face name
//      whole vertices and faces, each work vertex by the first whole vertex on it. Distortion stays
//      measured on the faces computed on. Returns, per work vertex, that first whole vertex.
#pragma once

#include <vector>

#include "maps/parameterization.h"
#include "mesh/mesh.h"

namespace meromorph {

std::vector<int> carry_back(const Mesh &whole, size_t work_vertex_count,
                            const std::vector<int> &vertex_in_work,
                            const std::vector<int> &face_in_work,
                            const ParameterizeOptions &options, Parameterization &map);

} // namespace meromorph
