// The closed surfaces a mesh as users bring it is made of: one per connected part, holes closed
// for the computation when asked.
//
// In:  a mesh that validation accepts apart from having several parts and, when `close_holes`,
//      boundary loops (holes); whether to close them.
// Out: `SurfaceParts`: per connected part (through shared edges; in the order of each part's
//      first face), a compact mesh with its vertices and faces in the input's order, every hole
//      closed by rings of new vertices shrinking to its loop's centroid (triangles about as large
//      as the loop's edges, oriented with the surface, so the part is closed and oriented), and for
//      every vertex and face its source in the input (-1 for what closing added); the holes closed
//      (part, loop length in edges, a vertex of it in the input's numbering, the faces added in the
//      part's numbering). Throws InputError when a hole's loop passes a vertex twice (two holes
//      touch there).
#pragma once

#include <deque>
#include <vector>

#include "mesh/mesh.h"

namespace meromorph {

struct ClosedHole {
  int part = 0;
  int edges = 0;
  int vertex = -1;        // a vertex of the loop, in the input's numbering
  std::vector<int> faces; // the faces that close it, in the part's numbering
};

struct SurfacePart {
  Mesh mesh;
  std::vector<int> source_vertex; // per part vertex: the input vertex, -1 for a hole's centre
  std::vector<int> source_face;   // per part face: the input face, -1 for a face closing a hole
};

struct SurfaceParts {
  std::deque<SurfacePart> parts; // built in place: vcglib's meshes cannot be moved or copied
  std::vector<ClosedHole> holes;
  std::vector<int> part_of_vertex, vertex_in_part; // per input vertex
  std::vector<int> part_of_face, face_in_part;     // per input face
};

SurfaceParts split_into_closed_parts(const Mesh &input, bool close_holes);

} // namespace meromorph
