// Branch points at vertices: a piecewise-linear map can only branch at a vertex.
//
// In:  a mesh and the map's value per vertex (modified in place).
// Out: where a critical point of the smooth map falls inside a face, the interpolated map folds a
//      few faces around it instead of winding twice around a vertex. Each such spot (vertices
//      that touch a folded face or wind less than once) is repaired: the map there is fitted by
//      c + k (z - p)^2 in a conformal coordinate z of the surface, and the vertex near p that then
//      winds twice with the fewest folded or flat faces around takes the critical value c (only
//      if that improves on leaving it). Returns how many vertices were moved.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "branch_points.h"
#include "mesh.h"
#include "sphere_geometry.h"

namespace meromorph {

int snap_branch_points(const Mesh &mesh, std::vector<PlaneValue> &values);

// A critical value known exactly (genus 1: P at a half period) goes to the candidate vertex
// (those nearest the critical point) that then winds twice with the fewest folded or flat faces
// around it. Returns that vertex.
int place_critical_value(const Mesh &mesh, std::vector<PlaneValue> &values,
                         const std::vector<int> &candidates, const PlaneValue &critical_value,
                         const std::vector<Eigen::Vector3d> &side_midpoints = {});

} // namespace meromorph
