// The intrinsic Delaunay triangulation of a closed mesh (Bobenko and Springborn 2007; Fisher,
// Springborn, Schroeder, Bobenko 2007): the same surface and the same vertices, with edges flipped
// on lengths alone until every edge's two opposite angles sum to at most pi. Its cotangent weights
// are non-negative, so harmonic functions and forms on it are free of the oscillations that
// needles and caps (negative weights) put into those of the mesh itself.
//
// In:  a mesh that validation accepted (closed, oriented, manifold) and its edges.
// Out: `IntrinsicDelaunay`: its edges (`MeshEdges`: faces in the same numbering as the mesh's,
//      vertices the mesh's; two edges may join the same two vertices), the length of every edge,
//      every face laid out flat on its own (`laid_out_flat`: FaceCorners, the corners of separate
//      triangles in the plane z = 0 in the face's order, built on request for the stages that work
//      per face), the number of flips, and `integrate_along_mesh_edges`: a closed 1-form on its
//      edges taken to the mesh's edges, each value the integral along a path homotopic to that mesh
//      edge (exact: every flip keeps the flipped edge as the two sides of one of its triangles).
//      Flips that would join a vertex to itself are skipped (the rare cost: an edge left
//      non-Delaunay).
//      `prepared_on_intrinsic_delaunay`: a prepared mesh (prepared_mesh.h) whose edges, weights
//      and edges at each vertex are this triangulation's (weights below 0 by rounding set to 0),
//      its faces, face geometry and vertex areas the mesh's own: for stages that solve on the
//      vertices (a Laplacian, rings of vertices) and judge the mesh's faces.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh/face_vectors.h"
#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"
#include "mesh/prepared_mesh.h"

namespace meromorph {

class IntrinsicDelaunay {
public:
  IntrinsicDelaunay(const Mesh &mesh, const MeshEdges &mesh_edges);

  const MeshEdges &edges() const { return edges_; }
  const std::vector<double> &lengths() const { return lengths_; }
  // Every face laid out flat on its own (see above), built on request.
  FaceCorners laid_out_flat() const;
  int flips() const { return int(retired_.size()); }

  // Cotangent weights (cot a + cot b) / 2 of the intrinsic triangulation, all >= 0 up to rounding.
  std::vector<double> cotan_weights() const;

  // A closed 1-form on this triangulation's edges -> its integrals along the mesh's edges.
  Eigen::VectorXcd integrate_along_mesh_edges(const Eigen::VectorXcd &form) const;

private:
  // An edge as it was before a flip: the two sides of one of its triangles (edge versions with
  // signs relative to its direction).
  struct Retired {
    int version;
    std::array<int, 2> sides;
    std::array<double, 2> signs;
  };

  bool flip_if_not_delaunay(int edge);

  MeshEdges edges_;
  std::vector<std::array<int, 3>> corners_; // per face
  std::vector<double> lengths_;
  std::vector<int> version_; // per edge slot: the version it holds now
  int next_version_ = 0;
  int mesh_edge_count_ = 0;
  std::vector<Retired> retired_; // in the order of the flips
};

PreparedMesh prepared_on_intrinsic_delaunay(const PreparedMesh &prepared);

} // namespace meromorph
