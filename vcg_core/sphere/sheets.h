// Layers (sheets) of a degree-d map: the preimage of the sphere cut along branch cuts.
//
// In:  a mesh, its edges, the sphere position per vertex, the branch vertices, the degree.
// Out: cuts are the great-circle arcs of the minimum spanning tree of the branch values (the sphere
//      minus a tree through every branch value is a disc, which holds no branch value: its
//      preimage falls into d sheets; the shortest tree cuts the fewest faces). Faces are joined
//      across edges whose image crosses no cut into components, the d largest being the sheets.
//      Faces at a branch vertex, faces whose image holds a branch value and folded faces are set
//      apart, as are edges from a vertex whose image lies on a cut and edges whose image is
//      shorter than 1e-6 (too short to tell which side of a cut they are on); they join the sheet
//      they continue across an uncut edge, or else any neighbour's. Per face and per vertex a layer
//      0..d-1, and the signed area of each layer over 4 pi (about 1 when each layer covers the
//      sphere once). Where the tree's layers do not each cover the sphere within 2% (a sheet in
//      two pieces, seen with nearly equal branch values), stars from the six directions
//      farthest from all branch values are tried too, and the labelling closest to one cover per
//      layer kept.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"

namespace meromorph {

struct Sheets {
  int count = 0;
  std::vector<int> face_layer;
  std::vector<int> vertex_layer;
  std::vector<double> coverage; // per layer: signed image area / 4 pi
  int cut_faces = 0;
};

Sheets label_sheets(const Mesh &mesh, const MeshEdges &edges,
                    const std::vector<Eigen::Vector3d> &sphere,
                    const std::vector<int> &branch_vertices, int degree);

} // namespace meromorph
