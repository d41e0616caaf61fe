// The main job on a mesh as users bring it: several parts, and holes when asked to close them.
//
// In:  a mesh that validation accepts, or that has several parts (each mapped on its own), or
//      holes (closed for the computation when `options.close_holes`, refused naming the option
//      otherwise); options (an origin vertex or pole face is the input's and applies to its part;
//      a form pair to every part of genus >= 2); progress.
// Out: one `Parameterization` in the input's numbering: a closed, connected mesh gets exactly
//      `parameterize`'s result; otherwise every input vertex and face gets its part's sphere
//      position, texture coordinates and layer (each part's texture fills the unit square on its
//      own, or its own cell of it with `options.pack_uv`; with several parts the layered spheres
//      stand side by side along x), the branch points of all parts, distortion measured on the
//      input's faces only, the degree, genus, Euler characteristic and ramification summed over the
//      parts, valid only when every part is, and `components` (each part's figures) and
//      `holes_closed`. Outputs hold the input's vertices and faces only: a closed hole shows as a
//      gap on the sphere. On a closed, connected mesh without defects whose own triangles cannot
//      carry the map, the vertices it needs are added (options.add_vertices; `added_vertices`,
//      `surface_faces`: parameterization.h; add_written_vertices below makes the written mesh).
//      With `options.split_nonmanifold`, non-manifold vertices and edges are first taken apart
//      (nonmanifold_split.h): the per-vertex arrays are then the split mesh's
//      (`sphere_faces`, `sphere_source_vertex`) and `nonmanifold_split` says what was split.
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "common/progress.h"
#include "maps/parameterization.h"
#include "mesh/mesh.h"
#include "mesh/validation.h"

namespace meromorph {

// The input is computed on in place (parameterize: moved to unit scale and put back exactly).
Parameterization parameterize_surface(Mesh &input, const ParameterizeOptions &options = {},
                                      const Progress &progress = {});

// The C++ entry point, on plain arrays (libigl's way); the C ABI calls it.
// In:  V: n x 3 vertex positions (double, any unit: the core computes at unit scale); F: m x 3
//      vertex indices of the triangles (0-based, counter-clockwise seen from outside). Any Eigen
//      matrix or map converts (a row-major one, or a map over flat x, y, z arrays, without a
//      copy). options, progress as above (the callback is called on this thread).
// Out: the map in V's and F's numbering: `sphere` (n unit vectors; with vertices added where F's
//      triangles cannot carry the map, options.add_vertices, n plus `added_vertices`, on the
//      triangles `surface_faces`), `layered`, `uv` (per vertex and per corner),
//      `sheets.vertex_layer`, `branch_points`, `degree`, `genus`, `valid` and
//      `invalid`, `quality` (distortion), `report` data (report/report_json.h turns it into the
//      JSON of `meromorph param`). The arrays are only read; nothing is kept after the call.
// Throws: InputError (what is wrong with the mesh, with vertex / face indices, and remedies),
//      ArgumentError (an option out of range), Cancelled (the callback said stop).
// Threads: any number of calls at once on different arrays.
using VertexPositions = Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>;
using TriangleCorners =
    Eigen::Ref<const Eigen::Matrix<int32_t, Eigen::Dynamic, 3, Eigen::RowMajor>>;
Parameterization parameterize_arrays(const VertexPositions &V, const TriangleCorners &F,
                                     const ParameterizeOptions &options = {},
                                     const Progress &progress = {});

// What parameterize_surface does with a finding of validation.h: maps the mesh as it is (several
// parts, zero-area faces), deals with it for the computation unless the options say not to
// (close_holes, split_nonmanifold, set_aside_defects: all on by default), maps it once the safe
// repairs of repair.h are applied first, or refuses it.
// `strict`: with none of those options (the first three handlings do not occur).
enum class FindingHandling { as_it_is, close_holes, split_nonmanifold, set_aside, repair, refused };
FindingHandling finding_handling(const Finding &finding, bool strict = false);

// The written surface: with vertices added (map.added_vertices), `input` gets them after its own
// and its faces become map.surface_faces; otherwise it stays as it is.
void add_written_vertices(const Parameterization &map, Mesh &input);

// The layered sphere as a mesh: `map.layered` positions on the input's faces (on the split
// mesh's vertices and faces when non-manifold spots were taken apart).
void layered_sphere_mesh(const Mesh &input, const Parameterization &map, Mesh &sphere);

} // namespace meromorph
