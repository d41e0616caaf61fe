// One closed part as every stage of the map reads it, built once.
//
// In:  a closed, connected, oriented manifold mesh that validation accepted, at unit scale
//      (unit_scale.h); it must outlive the structure.
// Out: `PreparedMesh`: the mesh, its oriented edges with their cotangent weights, the faces at
//      each vertex with every face's three vertices, the edges at each vertex, the face geometry
//      (areas; frames on request) and the area each vertex stands for (a third of its faces').
//      Stages take it by const reference and build none of it again.
#pragma once

#include <vector>

#include "mesh/face_vectors.h"
#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"

namespace meromorph {

struct PreparedMesh {
  const Mesh &mesh;
  MeshEdges edges;
  std::vector<double> weights; // cotangent weight per edge
  FaceIncidence incidence;
  IndexLists edges_at_vertex;
  FaceGeometry geometry;
  std::vector<double> vertex_areas;
};

PreparedMesh prepare_mesh(const Mesh &mesh);

// The same in two steps: the mesh and its edges (all the holomorphic forms read), then the rest.
// A caller that computes the forms in between does not hold the rest beside the Laplacian's
// factor (at 2.7M vertices 350 MB of the peak).
PreparedMesh prepare_mesh_edges(const Mesh &mesh);
void prepare_the_rest(PreparedMesh &prepared);

} // namespace meromorph
