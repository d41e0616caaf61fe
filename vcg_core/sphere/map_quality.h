// How conformal a map onto the sphere is, measured face by face.
//
// In:  a mesh, a unit-sphere position per vertex, and the vertices to stay away from (branch
//      points: the map is not locally injective there).
// Out: per face, the linear map from the triangle to the chord triangle of its image: its
//      quasi-conformal ratio sigma_max / sigma_min (1 for a similarity) and the mean absolute
//      difference of the three corner angles in degrees; a face is folded when its image has
//      non-positive signed spherical area or its chord triangle is not clearly positively
//      oriented (flat images at branch points count: a reader of the positions may see them
//      turned). Statistics overall and for the faces that do not touch a branch vertex:
//      quasi-conformal mean, 95th percentile and max, mean angle error, folded count, and the count
//      of collapsed faces, whose image's longest side is below 1e-14 (long thin parts shrink
//      exponentially under any conformal map; below that, double precision cannot tell their
//      orientation). Also the indices of the folded and of the collapsed faces.
#pragma once

#include <array>

#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"

namespace meromorph {

struct QualityStatistics {
  int faces = 0;
  double quasi_conformal_mean = 0, quasi_conformal_p95 = 0, quasi_conformal_max = 0;
  double angle_error_mean_degrees = 0;
  int folded_faces = 0;
  int collapsed_faces = 0; // image smaller than doubles resolve on the unit sphere (1e-14)
};

struct MapQuality {
  QualityStatistics overall;
  QualityStatistics away_from_branch_points;
  std::vector<int> folded_face_indices;    // every folded face, branch vertices included
  std::vector<int> collapsed_face_indices; // every collapsed face
};

// The mean absolute difference of a face's corner angles and its image's, in degrees; the second
// form with the face's own corner angles given (face_corner_angles, radians: the same result
// without working them out again).
double face_angle_error_degrees(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere,
                                int face);
std::array<double, 3> face_corner_angles(const Mesh &mesh, int face);
double face_angle_error_degrees(const std::array<double, 3> &corner_angles, const Mesh &mesh,
                                const std::vector<Eigen::Vector3d> &sphere, int face);

// Whether one face's image is folded as measure_map_quality judges it.
bool folded_as_measured(const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                        const Eigen::Vector3d &c);

// The mean angle error over all faces (measure_map_quality's, without the other measures).
double mean_angle_error_degrees(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere);

MapQuality measure_map_quality(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere,
                               const std::vector<int> &branch_vertices);

} // namespace meromorph
