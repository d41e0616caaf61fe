#include "job/map_files.h"

#include <numeric>
#include <vector>

#include "io/mesh_writer.h"
#include "job/surface_map.h"

namespace meromorph {

void write_surface(Mesh &mesh, const Parameterization &map, MeshFormat format,
                   const std::string &file) {
  for (size_t v = 0; v < mesh.vert.size(); ++v) {
    mesh.vert[v].T().U() = map.uv.vertex[v][0];
    mesh.vert[v].T().V() = map.uv.vertex[v][1];
    mesh.vert[v].Q() = map.sheets.vertex_layer[v]; // the layer, as MeshLab's quality
  }
  if (!mesh.face.IsWedgeTexCoordEnabled()) mesh.face.EnableWedgeTexCoord(); // mesh.h
  for (size_t f = 0; f < mesh.face.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      mesh.face[f].WT(k).U() = map.uv.wedge[f][k][0];
      mesh.face[f].WT(k).V() = map.uv.wedge[f][k][1];
      mesh.face[f].WT(k).N() = 0;
    }
  WriteOptions surface;
  surface.vertex_texcoords = surface.wedge_texcoords = surface.vertex_quality = true;
  save_mesh(mesh, format, file, surface);
}

void write_layered_sphere(const Mesh &mesh, const Parameterization &map, const std::string &file) {
  Mesh layered;
  layered_sphere_mesh(mesh, map, layered);
  WriteOptions sphere;
  std::vector<int> component = map.vertex_component;
  component.resize(layered.vert.size(), 0);
  std::vector<int> source_vertex = map.sphere_source_vertex;
  if (source_vertex.empty()) {
    source_vertex.resize(layered.vert.size());
    std::iota(source_vertex.begin(), source_vertex.end(), 0);
  }
  sphere.vertex_properties = {{"layer", map.sheets.vertex_layer, false},
                              {"branch", map.branch_flag, true},
                              {"source_vertex", source_vertex, false},
                              {"component", component, false}};
  save_mesh(layered, MeshFormat::ply, file, sphere);
}

} // namespace meromorph
