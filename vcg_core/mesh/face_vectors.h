// Closed 1-forms as vectors on faces, and the face geometry they need.
//
// In:  a mesh (or, for faces that share no corners, their corner positions: FaceCorners), its
//      oriented edges, and a closed 1-form (one value per edge).
// Out: per face, the unique vector a in the face's plane with <a, p_j - p_i> = form(ij) on its
//      three sides (the gradient of the linear function the form integrates to on that face);
//      face areas and frames (unit normal, first axis), corner angles, the area each vertex
//      stands for. The Hodge star of a face vector is n x a.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"

namespace meromorph {

// Per face its three corner positions: faces on their own, without a shared vertex (the
// intrinsic Delaunay triangulation's faces laid out flat), at 72 bytes a face.
using FaceCorners = std::vector<std::array<Eigen::Vector3d, 3>>;

// A face's unit normal and its unit first axis, along the side from corner 0 to corner 1.
struct FaceFrame {
  Eigen::Vector3d normal, first_axis;
};

// The faces' areas, and their frames computed from their corners when asked (stored, the frames
// took 48 bytes a face: 260 MB at 2.7M vertices). It reads the mesh or the corners it was made
// from, which must outlive it.
class FaceGeometry {
public:
  std::vector<double> areas;

  FaceFrame frame(size_t f) const;
  Eigen::Vector3d normal(size_t f) const;
  // The sides from corner 0 to corners 1 and 2.
  std::array<Eigen::Vector3d, 2> sides(size_t f) const;

private:
  friend FaceGeometry face_geometry(const Mesh &mesh);
  friend FaceGeometry face_geometry(const FaceCorners &faces);
  Eigen::Vector3d corner(size_t f, int k) const;

  const Mesh *mesh_ = nullptr;
  const FaceCorners *corners_ = nullptr;
};

FaceGeometry face_geometry(const Mesh &mesh);
FaceGeometry face_geometry(const FaceCorners &faces);

// The angle at corner k of a face, in radians.
double corner_angle(const MeshFace &face, int k);
// The corner angle at `at` between the sides to `to` and to `from` (radians).
double corner_angle(const Eigen::Vector3d &at, const Eigen::Vector3d &to,
                    const Eigen::Vector3d &from);

// The smallest of a face's three corner angles, in radians.
double smallest_angle(const MeshFace &face);

// A third of the area of every face around each vertex: the surface area a vertex stands for.
std::vector<double> vertex_areas(const Mesh &mesh);
std::vector<double> vertex_areas(const Mesh &mesh, const FaceGeometry &geometry);

// Face vectors, one row per face (F x 3).
Eigen::MatrixX3d face_vectors(const Mesh &mesh, const MeshEdges &edges,
                              const FaceGeometry &geometry, const Eigen::VectorXd &form);
Eigen::MatrixX3d face_vectors(const FaceCorners &faces, const MeshEdges &edges,
                              const FaceGeometry &geometry, const Eigen::VectorXd &form);
// One face's vectors for many forms without an array per form: the face's vector of any form is
// u1 * first + u2 * second, u1 the form along side 0 and u2 that plus the form along side 1.
struct FaceVectorBasis {
  Eigen::Vector3d first, second;
};
FaceVectorBasis face_vector_basis(const FaceCorners &faces, const FaceGeometry &geometry, size_t f);
FaceVectorBasis face_vector_basis(const Mesh &mesh, const FaceGeometry &geometry, size_t f);

} // namespace meromorph
