// A map computed without the mesh's zero-area faces (zero_area_faces.h), put back on the whole
// mesh.
//
// In:  the whole mesh, what taking its zero-area faces out did (`ZeroAreaFix`), the options, and
//      the map computed on the mesh without them.
// Out: the map on `whole`'s vertices and faces: a merged vertex takes the values of the vertex it
//      was merged into; a face that was collapsed or flipped takes its corners' texture
//      coordinates (unwrapped across the seam) and its first corner's layer; then the zero-area
//      faces' images are oriented (zero_area_images.h), the layered sphere and the texture
//      coordinates following the moved vertices. Distortion stays measured on the faces computed
//      on.
#pragma once

#include "maps/parameterization.h"
#include "mesh/mesh.h"
#include "mesh/zero_area_faces.h"

namespace meromorph {

void with_zero_area_faces(const Mesh &whole, const ZeroAreaFix &fix,
                          const ParameterizeOptions &options, Parameterization &map);

} // namespace meromorph
