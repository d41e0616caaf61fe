#include "mesh/prepared_mesh.h"

#include "mesh/cotan_laplacian.h"

namespace meromorph {

PreparedMesh prepare_mesh(const Mesh &mesh) {
  PreparedMesh out{mesh, build_mesh_edges(mesh), {}, face_incidence(mesh),
                   {},   face_geometry(mesh),    {}};
  out.weights = cotan_weights(mesh, out.edges);
  out.edges_at_vertex = edges_at_vertices(out.edges, int(mesh.vert.size()));
  out.vertex_areas = vertex_areas(mesh, out.geometry);
  return out;
}

} // namespace meromorph
