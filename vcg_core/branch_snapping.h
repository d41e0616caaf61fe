// Branch points at vertices: a piecewise-linear map can only branch at a vertex.
//
// In:  a mesh, the map's value per vertex (modified in place), and candidate critical values known
//      exactly (may be empty).
// Out: where a critical point of the smooth map falls inside a face, the interpolated map folds a
//      few faces around it instead of winding twice around a vertex. Each such spot (a cluster of
//      vertices that touch a folded face or wind other than once) is repaired by moving the image
//      of one of its vertices onto the critical value: the candidates are the cluster's vertices,
//      the values are the exact ones given plus the images of the spot's vertices and their mean,
//      and the choice is the one that leaves the fewest folded faces nearby (only if that improves
//      on leaving it). Returns how many vertices were moved.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "mesh.h"
#include "sphere_geometry.h"

namespace meromorph {

int snap_branch_points(const Mesh &mesh, std::vector<PlaneValue> &values,
                       const std::vector<PlaneValue> &critical_values = {});

// A critical value known exactly (genus 1: P at a half period) goes to the candidate vertex
// (those nearest the critical point) that then winds twice with the fewest folded or flat faces
// around it. Returns that vertex.
int place_critical_value(const Mesh &mesh, std::vector<PlaneValue> &values,
                         const std::vector<int> &candidates, const PlaneValue &critical_value,
                         const std::vector<Eigen::Vector3d> &side_midpoints = {});

} // namespace meromorph
