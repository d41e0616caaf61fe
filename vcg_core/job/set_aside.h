// What the computation leaves out of a mesh as users bring it, so that the outputs can still hold
// every input vertex and face in the input's order.
//
// In:  a mesh and its validation (validation.h).
// Out: `SetAside`: `work`, the mesh the map is computed on: seam duplicates (finding
//      duplicate_vertices: coinciding vertices on the edges of holes) welded into the vertex they
//      sit on, then faces that use a vertex twice and faces on the same three vertices as an
//      earlier face (doubled faces) left out, then vertices on no face left out; vertices and faces
//      in the input's order, each face's corners in the input face's order. `vertex_in_work` per
//      input vertex (-1: on no face of `work`), `face_in_work` per input face (-1: left out), and
//      one note per kind of change, in the user's words, for the report.
//      `has_defects_to_set_aside`: whether the validation found any of these.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/validation.h"

namespace meromorph {

struct SetAside {
  Mesh work;
  std::vector<int> vertex_in_work, face_in_work;
  std::vector<std::string> notes;
};

bool has_defects_to_set_aside(const Validation &validation);

void set_aside_defects(const Mesh &input, const Validation &validation, SetAside &out);

} // namespace meromorph
