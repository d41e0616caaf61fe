// The files of a map: the surface with its texture coordinates and the layered sphere.
//
// In:  the surface as written (the input mesh, with add_written_vertices applied) and its map.
// Out: `write_surface`: the surface in `format` with per-vertex and per-wedge texture coordinates
//      and each vertex's layer as MeshLab's quality; `write_layered_sphere`: a PLY of the layered
//      sphere with per-vertex layer, branch, source_vertex and component. Both write exactly the
//      path given (a staged temporary path: io/staged_outputs.h).
// Errors: WriteError (io/mesh_writer.h) when writing fails.
#pragma once

#include <string>

#include "io/mesh_format.h"
#include "maps/parameterization.h"
#include "mesh/mesh.h"

namespace meromorph {

// `mesh` gets the map's texture coordinates and layers before it is written.
void write_surface(Mesh &mesh, const Parameterization &map, MeshFormat format,
                   const std::string &file);

void write_layered_sphere(const Mesh &mesh, const Parameterization &map, const std::string &file);

} // namespace meromorph
