// Moebius normalisation: the Moebius transformation of the sphere that puts the centroid of the
// image at the origin (Springborn; Baden, Crane, Kazhdan 2018, "Moebius registration").
//
// In:  values of the extended plane (the map before projection) and a weight per value (the
//      surface area each vertex stands for).
// Out: the values moved, in place, by a Moebius transformation composed of hyperbolic translations
//      of the ball x -> (1 - |c|^2)(x - c) / |x - c|^2 - c, each chosen by a Newton step, until the
//      weighted centroid of the projected points is below 1e-12 in norm. The transformation is
//      applied in the plane (as a 2 x 2 complex matrix, found from three points) to the original
//      values, so points crowded near a pole keep their full relative precision. Orientation is
//      preserved. Returns the centroid before and after, the steps and the transformation.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "sphere/sphere_geometry.h"

namespace meromorph {

struct MobiusCentering {
  Eigen::Vector3d centroid_before = Eigen::Vector3d::Zero();
  Eigen::Vector3d centroid_after = Eigen::Vector3d::Zero();
  int steps = 0;
  Mobius transformation;
};

MobiusCentering center_on_sphere(std::vector<PlaneValue> &values,
                                 const std::vector<double> &weights);

// Values as center_on_sphere left them, with what it did: for a caller that centred a map
// already (to judge it) to hand on instead of centring it again.
struct CentredValues {
  std::vector<PlaneValue> values;
  MobiusCentering centring;
};

// The hyperbolic translation of the ball by c (|c| < 1) on a unit vector x, and the same as a
// transformation of the extended plane (stereographic coordinates).
Eigen::Vector3d ball_translate(const Eigen::Vector3d &x, const Eigen::Vector3d &c);
Mobius translation_matrix(const Eigen::Vector3d &c);

// Weighted centroid.
Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d> &points,
                         const std::vector<double> &weights);

} // namespace meromorph
