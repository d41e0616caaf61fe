// Several parts, or holes to close: each part mapped on its own, in the mesh's numbering.
//
// In:  a mesh whose validation found several parts and/or holes (nothing else that the map
//      cannot take), its validation, options (an origin vertex or pole face is the mesh's and
//      applies to its own part only), progress (shared out over the parts).
// Out: one `Parameterization` in the mesh's numbering: every vertex and face gets its part's
//      sphere position, texture coordinates and layer (each part's texture fills the unit square
//      on its own, or its own cell of it with `options.pack_uv`; with several parts the layered
//      spheres stand side by side along x), the branch points of all parts, the degree, genus,
//      Euler characteristic and ramification summed over the parts, valid only when every part
//      is, each part's own figures in `components`, `holes_closed` (the gap each closed hole
//      leaves on the sphere), and distortion measured on the mesh's own faces only.
#pragma once

#include "common/progress.h"
#include "maps/parameterization.h"
#include "mesh/mesh.h"
#include "mesh/validation.h"

namespace meromorph {

// The side of the square grid whose cells hold `part_count` parts' packed texture coordinates.
int texture_grid_cells(size_t part_count);

// The mesh is moved to unit scale for the distortion's measurement and put back exactly.
Parameterization parameterize_parts(Mesh &mesh, const Validation &validation,
                                    const ParameterizeOptions &options, const Progress &progress);

} // namespace meromorph
