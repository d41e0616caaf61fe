#include "mesh/mesh_from_arrays.h"

#include <string>

#include "common/errors.h"

namespace meromorph {

void mesh_from_arrays(const MeshArrays &arrays, Mesh &mesh) {
  const int vertex_count = int(arrays.positions.size());
  for (size_t f = 0; f < arrays.triangles.size(); ++f)
    for (int index : arrays.triangles[f])
      if (index < 0 || index >= vertex_count)
        throw InputError("face " + std::to_string(f) + " refers to vertex " +
                         std::to_string(index) + ", but there are only " +
                         std::to_string(vertex_count) + " vertices (0.." +
                         std::to_string(vertex_count - 1) + ")");

  mesh.Clear();
  auto first_vertex = vcg::tri::Allocator<Mesh>::AddVertices(mesh, arrays.positions.size());
  for (size_t v = 0; v < arrays.positions.size(); ++v)
    first_vertex[v].P() = arrays.positions[v];
  auto first_face = vcg::tri::Allocator<Mesh>::AddFaces(mesh, arrays.triangles.size());
  for (size_t f = 0; f < arrays.triangles.size(); ++f)
    for (int corner = 0; corner < 3; ++corner)
      first_face[f].V(corner) = &mesh.vert[arrays.triangles[f][corner]];
}

MeshArrays arrays_from_mesh(const Mesh &mesh) {
  MeshArrays arrays;
  std::vector<int> dense_index(mesh.vert.size(), -1);
  arrays.positions.reserve(mesh.VN());
  for (size_t v = 0; v < mesh.vert.size(); ++v) {
    if (mesh.vert[v].IsD()) continue;
    dense_index[v] = int(arrays.positions.size());
    arrays.positions.push_back(mesh.vert[v].cP());
  }
  arrays.triangles.reserve(mesh.FN());
  for (const auto &face : mesh.face) {
    if (face.IsD()) continue;
    arrays.triangles.push_back({dense_index[index_of(mesh, face.cV(0))],
                                dense_index[index_of(mesh, face.cV(1))],
                                dense_index[index_of(mesh, face.cV(2))]});
  }
  return arrays;
}

} // namespace meromorph
