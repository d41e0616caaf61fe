// Zero-area faces taken out of the computation, so the map is computed on a triangulation of the
// same surface without them and the outputs still hold every input face.
//
// In:  a mesh whose zero-area faces (validation.h: has_zero_area) are the trouble: needles (two
//      corners at or next to the same point) and caps (three corners on a line).
// Out: `work`, the mesh without them: a needle's shortest edge is collapsed (its later vertex
//      merged into the earlier, the two faces on the edge gone), a cap whose middle vertex has no
//      other face than the cap and the two beside it (a T-junction) has that vertex merged into
//      the nearer end of its long side (the face it split comes back), any other cap's longest
//      edge is flipped with the face across it (no vertex moves), repeated until none is left; and
//      `ZeroAreaFix`: for every input vertex its vertex in `work` (vertices in the input's order,
//      merged ones left out), for every input face its face in `work` when it is there with the
//      same corners
//      (-1 for faces that were collapsed or flipped), and the zero-area faces found. Throws
//      InputError naming the face when one cannot be taken out (a collapse that would change the
//      topology, a cap whose longest edge is on a hole or cannot be flipped).
#pragma once

#include <vector>

#include "mesh/mesh.h"

namespace meromorph {

struct ZeroAreaFix {
  std::vector<int> vertex_in_work; // per input vertex
  std::vector<int> face_in_work;   // per input face, -1 where it changed
  std::vector<int> zero_area_faces;
  int collapsed_edges = 0, flipped_edges = 0;
};

ZeroAreaFix take_out_zero_area_faces(const Mesh &input, Mesh &work);

} // namespace meromorph
