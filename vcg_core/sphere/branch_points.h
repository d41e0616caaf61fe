// Degree, local degrees and branch points of a map from the mesh onto the sphere.
//
// In:  a mesh and a unit-sphere position per vertex (the map, linear on each face), its Euler
//      characteristic.
// Out: the local degree e of every vertex: the winding number of its one-ring's image around the
//      vertex's image, measured in the stereographic chart centred at that image (e >= 2: a
//      branch point of order e - 1; e <= 0: a fold); the degree d: total signed spherical area of
//      the face images over 4 pi; and the Riemann-Hurwitz check chi = 2 d - sum (e - 1).
//      `side_midpoints`, when given (3 per face: the image of the midpoint of the side opposite
//      each corner), refine the one-ring: the map doubles angles at a double point, so a corner
//      of 90 degrees or more there sweeps half a turn or more, which its two ends alone cannot
//      tell from a fold; the smooth map's value between them can.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"

namespace meromorph {

struct Branching {
  std::vector<int> local_degree;    // per vertex
  std::vector<int> branch_vertices; // e >= 2
  int ramification = 0;             // sum over vertices of (e - 1)
  double area_over_4pi = 0;         // before rounding
  int degree = 0;
  bool riemann_hurwitz_ok = false;
};

Branching analyse_branching(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere, int euler,
                            const std::vector<Eigen::Vector3d> &side_midpoints = {});

// The angle the image of the side of face `face` opposite corner k sweeps around that corner.
double corner_sweep(const std::vector<Eigen::Vector3d> &sphere, const std::array<int, 3> &corners,
                    int k, const std::vector<Eigen::Vector3d> &side_midpoints, int face);

// Folded: face f's image turned over (sphere_geometry.h's folded_image).
bool folded_face(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere, int face);

// Folded or flat: a face whose image is not positively oriented by a margin (1e-9 of its longest
// chord squared): what a repair of the map must not leave behind.
bool folded_or_flat(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere, int face);

// The local degree of the written map at `vertex` (side_midpoints as in analyse_branching).
int vertex_winding(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere, int vertex,
                   const std::vector<Eigen::Vector3d> &side_midpoints = {});

// Signed spherical area of each face's image.
std::vector<double> face_solid_angles(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere);

// The map's total signed image area over 4 pi (its degree before rounding): the sum of the
// faces' signed solid angles, an integer up to rounding for a map of a closed surface.
double image_area_over_4pi(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere);

} // namespace meromorph
