// Remedies: what the user can do about a refusal or an invalid map, as codes that each adapter
// words for its own users (the CLI names its flags, MeshLab its menus and filter parameters,
// Blender its menus and operator options). The core never names a flag or a menu.
//
// In:  nothing (a closed list).
// Out: `Remedy` (stable numbers: the C ABI hands them out) and its JSON name; `Advice`, a cause
//      found on the mesh or map (with its figures and places, in words that name no tool) and the
//      remedy for it.
#pragma once

#include <string>
#include <vector>

namespace meromorph {

enum class Remedy : int {
  repair = 1,                 // safe repairs: merge seam duplicates, drop unused vertices, orient
  close_holes = 2,            // close the holes (for the computation only, or in the model)
  split_nonmanifold = 3,      // take non-manifold spots apart for the computation
  remove_zero_area_faces = 4, // optional: param already keeps them out of the computation
  remove_duplicate_faces = 5, // doubled faces on the same three vertices
  remesh = 6,                 // needles and caps: an isotropic remesh
  refine = 7,                 // too coarse near the branch points: subdivide
  generic_form_pair = 8,      // a chosen genus >= 2 form pair is nearly 0 / 0: use the default
  shorten_thin_parts = 9,     // long thin parts shrink below double precision
  check_units = 10,           // a stray vertex far away, or coordinates in different units
  choose_uv_kind = 11,        // packing is for spherical texture coordinates only
  add_vertices = 12,          // let the map add the vertices the triangulation lacks
};

constexpr Remedy last_remedy = Remedy::add_vertices;

struct Advice {
  std::string cause;
  Remedy remedy;
};

// "close_holes", ...: the name in JSON reports.
const char *remedy_code(Remedy remedy);

} // namespace meromorph
