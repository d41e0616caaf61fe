// Lifting points and arcs of the sphere to a surface mapped onto it: where on the surface the map
// takes a given value.
//
// In:  `MappedSurface`: the surface's faces (three vertices each, oriented), the face across each
//      side (side k joins corners k and k + 1; -1 at a boundary) and the unit-sphere image of each
//      vertex (the map is taken linear on each face's flat image triangle and projected from the
//      centre, so lines of the image plane are great circles and a value's barycentric
//      coordinates are ratios of determinants). `points_over`: a value q. `lift_arc`: a start
//      point on the surface, its image a and a target value b (a and b less than half a turn
//      apart).
// Out: `points_over`: every point of the surface whose image is q (a face and barycentric
//      coordinates; found by testing every face; a point on a side or corner is given once).
//      `lift_arc`: the end of the arc's lift: the path that starts at the start point and whose
//      image runs along the great-circle arc from a to b, walked face by face across sides; empty
//      when it runs off a boundary or does not arrive within `max_steps` faces (a folded image).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace meromorph {

struct MappedSurface {
  std::vector<std::array<int, 3>> faces;
  std::vector<std::array<int, 3>> across; // per face, per side
  std::vector<Eigen::Vector3d> image;     // per vertex, unit
  std::vector<Eigen::Vector3d> positions; // per vertex, on the surface
};

struct SurfacePoint {
  int face = -1;
  Eigen::Vector3d weights = Eigen::Vector3d::Zero(); // barycentric, per corner
};

Eigen::Vector3d position_of(const MappedSurface &surface, const SurfacePoint &point);

std::vector<SurfacePoint> points_over(const MappedSurface &surface, const Eigen::Vector3d &q);

// `path`, when given, gets the lift's points where it enters each face after the first, and its
// end: the surface point and the parameter t of the chord (1 - t) a + t b there.
struct PathPoint {
  SurfacePoint point;
  double t = 0;
};

// `boundary_exit`, when given and the lift runs off a boundary, gets the point of the boundary
// where it leaves the surface and its chord parameter t (its face is -1 otherwise).
std::optional<SurfacePoint> lift_arc(const MappedSurface &surface, const SurfacePoint &start,
                                     const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                                     int max_steps, std::vector<PathPoint> *path = nullptr,
                                     PathPoint *boundary_exit = nullptr);

} // namespace meromorph
