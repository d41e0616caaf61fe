// Branch points at vertices: a piecewise-linear map can only branch at a vertex.
//
// In:  a mesh, its edges, the map's value per vertex (modified in place), and holomorphic 1-forms
//      that give conformal coordinates of the surface (genus >= 2: the numerator and denominator
//      of the ratio, which have no common zero).
// Out: where a critical point p of the smooth map falls inside a face, the interpolated map folds
//      that face instead of winding twice around a vertex. Each such spot (vertices that touch a
//      folded face or wind less than once) is repaired: in the coordinate z = integral of the
//      larger form, the map is fitted by Q(z) = c + k (z - p)^2, and the map is composed with a
//      small local shift of the surface that takes a vertex v near p onto p: within one ring of v
//      the values become Q(z + p - z_v) (v gets the critical value c), fading to the measured
//      values over the next rings. Where doubling v's corners would reach 180 degrees (obtuse
//      stars), a variant also re-places v's one-ring around c: each neighbour keeps its distance,
//      its direction follows the doubled corners capped at 170 degrees, and, where that folds the
//      faces beyond the star, with the next one or two rings re-embedded about the critical value
//      (branch_star.h). Of the vertices nearest p
//      and these variants, the one that leaves the fewest folded or flat faces wins, if that
//      improves on leaving the spot alone. A spot holding two critical points is fitted by a cubic
//      and one of its critical points is placed per pass. A spot whose windings
//      and folded faces add up to no critical point (sum of e - 1 plus folded faces <= 0) has a
//      stray vertex value instead (next to needle-shaped faces): its values are smoothed towards
//      their neighbours', if that leaves fewer folded faces. Returns how many spots were
//      repaired.
//      `left_alone` (optional, kept by the caller between passes over the same map with the same
//      forms): the spots a pass left as they were (nothing improved on them), each with the
//      vertices whose values that decision read. A later pass that finds such a spot again, the
//      same vertices, none of those values changed since, skips it: it would decide the same
//      (a spot's repair reads nothing else). The same result as without it, in less time.
#pragma once

#include <map>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"
#include "mesh/prepared_mesh.h"
#include "sphere/branch_points.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {

// A spot's vertices -> the vertices whose values its decision read.
using SpotsLeftAlone = std::map<std::vector<int>, std::vector<int>>;

int snap_branch_points(const PreparedMesh &prepared,
                       const std::vector<const Eigen::VectorXcd *> &coordinate_forms,
                       std::vector<PlaneValue> &values, SpotsLeftAlone *left_alone = nullptr);

} // namespace meromorph
