// Aligning two genus-0 maps: the Moebius transformation of the sphere that takes the source's
// sphere onto the target's so that corresponding points meet.
//
// In:  per vertex of each surface, its point on the unit sphere (Moebius-centred maps), its
//      triangles, and a function on its vertices that does not depend on the triangulation, the
//      placement or the size (`log_conformal_factor`); landmark pairs (source vertex, target
//      vertex) when the user gives them.
// Out: `SphereAlignment`: x -> R ball_translate(M(x), c) (M a Moebius transformation of the plane
//      in stereographic coordinates, c a hyperbolic translation of the ball, R a rotation), how it
//      was found, the landmarks' distance on the sphere after it, and for the automatic alignment
//      the other rotations that fit almost as well (a symmetric surface has several): within a
//      fifth of the way from the best to what a rotation at random costs. `align_by_landmarks`:
//      three pairs fix it exactly (the Moebius transformation through them); more are fitted in
//      least squares from the three most spread out. `align_by_functions`: the rotation that best
//      matches the two functions over the sphere (both maps centred: what is left between them is a
//      rotation), by a coarse search over rotations refined by a local search.
// Errors: InputError for landmarks that cannot fix a transformation (fewer than three, or points
//      that coincide on the sphere).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "sphere/sphere_geometry.h"

namespace meromorph {

struct SphereAlignment {
  Mobius plane;                                           // M
  Eigen::Vector3d ball = Eigen::Vector3d::Zero();         // c
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity(); // R
  std::string method;
  double landmark_distance_max = 0; // on the unit sphere, after the alignment
  double cost = 0;                  // automatic: mean squared difference of the functions
  struct Alternative {
    double angle_from_best_degrees = 0;
    double cost = 0;
  };
  std::vector<Alternative> alternatives;

  Eigen::Vector3d apply(const Eigen::Vector3d &x) const;
  Eigen::Vector3d apply_inverse(const Eigen::Vector3d &y) const;
};

// Per vertex: log of (its share of the surface's area) / (its share of the image's: the sphere,
// the flat torus; `image_areas` per triangle), the conformal factor in a form that rigid motion,
// scale and refinement leave alone.
std::vector<double> log_conformal_factor(const std::vector<Eigen::Vector3d> &positions,
                                         const std::vector<std::array<int, 3>> &triangles,
                                         const std::vector<double> &image_areas);

SphereAlignment align_by_landmarks(const std::vector<Eigen::Vector3d> &source_sphere,
                                   const std::vector<Eigen::Vector3d> &target_sphere,
                                   const std::vector<std::pair<int, int>> &landmarks);

// Every Moebius transformation that takes the points `a` onto the points `b` as sets (the same
// count; the branch values of two maps of the same degree): through the three most spread points
// of `a` and each ordered triple of `b`, kept where every point of `a` lands within `tolerance`
// (chordal) of a point of `b`. Best first; `landmark_distance_max` is that largest distance.
std::vector<SphereAlignment> align_point_sets(const std::vector<Eigen::Vector3d> &a,
                                              const std::vector<Eigen::Vector3d> &b,
                                              double tolerance);

class SphereTriangleGrid;
// A function given at the vertices of a triangulated sphere, and the grid of its triangles.
struct SphereFunction {
  const std::vector<std::array<int, 3>> &triangles;
  const SphereTriangleGrid &grid;
  const std::vector<double> &values;
};
SphereAlignment align_by_functions(const SphereFunction &source, const SphereFunction &target);

} // namespace meromorph
