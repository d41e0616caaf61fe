// How good a remeshed surface is, measured against the surface it was sampled from.
//
// In:  the input surface and the remeshed one (any meshes; their positions and faces), the local
//      degree of every remeshed vertex (>= 2 at branch vertices, else 0).
// Out: `RemeshQuality`: vertex, edge and face counts, Euler characteristic, boundary and
//      non-manifold edges and non-manifold vertices (vcglib's clean.h); the Hausdorff distance
//      both ways over the input's bounding-box diagonal (vcglib's HausdorffSampler: every vertex
//      and two random samples per face of one mesh against the other's faces) with the mean
//      distances; the minimum and mean corner angle in degrees, over all faces and over the faces
//      that touch no branch vertex; the valence histogram (valence, vertices).
#pragma once

#include <utility>
#include <vector>

#include "mesh/mesh.h"

namespace meromorph {

struct RemeshQuality {
  int vertices = 0, edges = 0, faces = 0, euler = 0;
  int boundary_edges = 0, nonmanifold_edges = 0, nonmanifold_vertices = 0;
  double hausdorff_to_input = 0, hausdorff_from_input = 0; // over the diagonal
  double mean_distance_to_input = 0, mean_distance_from_input = 0;
  double min_angle_degrees = 0, mean_angle_degrees = 0, min_angle_away_from_branch_degrees = 0;
  std::vector<std::pair<int, int>> valence_histogram;
};

RemeshQuality measure_remesh(const Mesh &input, const Mesh &remeshed,
                             const std::vector<int> &local_degree);

} // namespace meromorph
