#include "mesh/prepared_mesh.h"

#include "mesh/cotan_laplacian.h"

namespace meromorph {

PreparedMesh prepare_mesh(const Mesh &mesh) {
  PreparedMesh out = prepare_mesh_edges(mesh);
  prepare_the_rest(out);
  return out;
}

PreparedMesh prepare_mesh_edges(const Mesh &mesh) {
  return PreparedMesh{mesh, build_mesh_edges(mesh), {}, {}, {}, {}, {}};
}

void prepare_the_rest(PreparedMesh &prepared) {
  const Mesh &mesh = prepared.mesh;
  prepared.incidence = face_incidence(mesh);
  prepared.geometry = face_geometry(mesh);
  prepared.weights = cotan_weights(mesh, prepared.edges);
  prepared.edges_at_vertex = edges_at_vertices(prepared.edges, int(mesh.vert.size()));
  prepared.vertex_areas = vertex_areas(mesh, prepared.geometry);
}

} // namespace meromorph
