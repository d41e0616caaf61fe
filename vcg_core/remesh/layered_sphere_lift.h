// The layered sphere mesh lifted to the surface: the remeshed surface of one part.
//
// In:  the mapped surface (path_lifting.h), the layer of each of its faces, the local degree of
//      each of its vertices (>= 2 at branch points), the degree d of the map, the sphere mesh to
//      sample (geodesic_sphere.h, branch values on vertices) and progress (cancellable).
// Out: `LiftedSphere`: every vertex of the sphere mesh lifted d times (the points of the surface
//      over it; fewer at a branch value, where sheets meet), found by path lifting from one vertex
//      over which d points are found directly, along the sphere mesh's edges (walks start only
//      at vertices that carry no branch value, so every lift is unambiguous); every sphere face
//      lifted d times, its corners joined the way the lifts of its edges join them, which glues
//      the d copies across the cuts as the map's sheets are glued (the monodromy around each
//      branch value) without cutting anything. Per lifted vertex its surface position (on a
//      face of the surface, interpolated), sphere value, layer (of the surface face it lies in),
//      local degree (at a surface branch vertex, else 0) and surface point; faces oriented as the
//      surface. A surface with holes leaves gaps on the sphere: a face copy with a corner in the
//      gap is cut where the lifts of its sides leave the surface (vertices on the boundary, which
//      stay put later; a cut a hair from a lift is that lift, two cuts a hair apart are one), so
//      the remesh's holes follow the input's. Also what did not lift (a copy with a side whose
//      lift neither arrives nor leaves by a boundary, or a cut needing a walk from a branch
//      value), faces whose three edge lifts do not close (a folded image), and folded lifts:
//      faces whose normal points against the surface's.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "common/progress.h"
#include "remesh/geodesic_sphere.h"
#include "remesh/path_lifting.h"

namespace meromorph {

struct LiftedSphere {
  std::vector<Eigen::Vector3d> positions, sphere;
  std::vector<int> layer, local_degree;
  std::vector<SurfacePoint> surface_point;
  // Per vertex: whether it lies on the surface's boundary, where the lift of a sphere edge runs off
  // a hole (such vertices stay where they are).
  std::vector<char> on_boundary;
  std::vector<std::array<int, 3>> faces;
  int unlifted_faces = 0, unclosed_faces = 0, folded_lifts = 0;
  std::vector<Eigen::Vector3d> unclosed_at; // the sphere faces' centres
};

LiftedSphere lift_sphere(const MappedSurface &surface, const std::vector<int> &face_layer,
                         const std::vector<int> &local_degree, int degree,
                         const GeodesicSphere &sphere, const Progress &progress = {});

// Whether a lifted face's normal points against the surface's normals at its corners' points (their
// sum), or more than 120 degrees away from the normal at one corner (across a thin part's rim).
bool lifted_face_folds(const MappedSurface &surface, const LiftedSphere &lifted,
                       const std::array<int, 3> &face);

// A lifted face's smallest corner angle on the surface (radians).
double smallest_corner_angle(const LiftedSphere &lifted, const std::array<int, 3> &face);
// Whether a lifted face is positively oriented on the sphere (its sphere values counter-clockwise
// seen from outside).
bool positive_on_sphere(const LiftedSphere &lifted, const std::array<int, 3> &face);

// Lifted faces whose normal points against the surface's normals at their corners' points.
int count_folded_lifts(const MappedSurface &surface, const LiftedSphere &lifted);

// Two boundary vertices a hair apart make a sliver: where a face's side between two boundary
// vertices is under a tenth of its longest side, the two become one (the face goes), if they
// share no neighbour but that face's third corner (the surface stays a manifold). Up to three
// passes; folded lifts recounted when anything was joined. Nothing to do without a boundary.
void join_near_boundary_vertices(const MappedSurface &surface, LiftedSphere &lifted);

// Folded faces along a hole's boundary (a side on no other face, the corner across it on a
// closed fan of faces, so the surface stays a manifold) are taken out, pass by pass; returns how
// many. Where the boundary bends between two cuts, the face between them can turn over.
int drop_folded_boundary_faces(const MappedSurface &surface, LiftedSphere &lifted);

} // namespace meromorph
