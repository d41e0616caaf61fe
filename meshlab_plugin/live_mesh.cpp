#include "live_mesh.h"

int report_progress(double fraction, const char *stage, void *user) {
  ProgressBridge *bridge = static_cast<ProgressBridge *>(user);
  // MeshLab's callback returns false to stop (MeshLab 2020.09's own never does).
  return !bridge->callback || bridge->callback(int(100 * fraction), stage) ? 1 : 0;
}

LiveMesh live_mesh(CMeshO &mesh) {
  LiveMesh live;
  live.dense.assign(mesh.vert.size(), -1);
  for (size_t v = 0; v < mesh.vert.size(); ++v) {
    if (mesh.vert[v].IsD()) continue;
    live.dense[v] = int(live.live_of_dense.size());
    live.live_of_dense.push_back(int(v));
    for (int k = 0; k < 3; ++k)
      live.positions.push_back(float(mesh.vert[v].P()[k]));
  }
  for (CFaceO &face : mesh.face) {
    if (face.IsD()) continue;
    for (int k = 0; k < 3; ++k)
      live.triangles.push_back(live.dense[vcg::tri::Index(mesh, face.V(k))]);
    live.faces.push_back(&face);
  }
  return live;
}
