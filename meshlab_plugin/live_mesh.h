// What the plugin's filters share to hand MeshLab's mesh to the C library: the live (not deleted)
// vertices and faces numbered densely, as arrays; and MeshLab's progress callback as the
// library's.
//
// In:  a CMeshO (may hold deleted elements); MeshLab's vcg::CallBackPos.
// Out: `LiveMesh` (positions as floats, triangles, the live number of every vertex and the live
//      faces); `report_progress` with a `ProgressBridge` as meromorph_options.progress(_user).
#ifndef MEROMORPH_LIVE_MESH_H
#define MEROMORPH_LIVE_MESH_H

#include <common/ml_mesh_type.h>
#include <vector>

struct ProgressBridge {
  vcg::CallBackPos *callback;
};

int report_progress(double fraction, const char *stage, void *user);

struct LiveMesh {
  std::vector<int> dense; // per vertex of the mesh: its live number, -1 when deleted
  std::vector<int> live_of_dense;
  std::vector<float> positions;
  std::vector<int32_t> triangles;
  std::vector<CFaceO *> faces;
  size_t vertex_count() const { return positions.size() / 3; }
};

LiveMesh live_mesh(CMeshO &mesh);

#endif
