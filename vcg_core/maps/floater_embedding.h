// Floater's embedding of part of a mesh in a plane chart of the sphere.
//
// In:  the mesh (its surface gives the weights), face incidence, the free vertices, and a chart
//      position for each of them and each vertex next to them (the fixed ones stay).
// Out: each free vertex at the mean of its neighbours weighted by mean-value weights of the
//      surface, (tan(alpha / 2) + tan(beta / 2)) / |ij| with alpha, beta the angles at it of the
//      two faces on the edge: positive on any triangulation, so there is no fold when the fixed
//      rim is convex (Floater 2003). Solved at once: as a dense matrix up to 64 free vertices
//      (branch snapping's thousands of small regions), by Eigen's sparse LU above.
//      False, nothing changed, where a weight is not finite (an edge of zero length), a fixed
//      neighbour has no position or the system cannot be solved (free vertices out of reach of
//      every fixed one).
//      Also the gnomonic chart at a point of the sphere, which maps great circles to lines, so a
//      face's orientation on the sphere is its orientation there.
#pragma once

#include <map>
#include <memory_resource>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"

namespace meromorph {

// Chart positions by vertex, their nodes from a memory resource the caller chooses (a buffer on
// the stack for the small regions of branch snapping, which makes thousands of them).
using PlanePositions = std::pmr::map<int, Eigen::Vector2d>;

bool floater_embedding(const Mesh &mesh, const FaceIncidence &incidence,
                       const std::vector<int> &free, PlanePositions &chart);

struct GnomonicChart {
  explicit GnomonicChart(const Eigen::Vector3d &centre);
  // False when p is less than 0.1 above the plane through the origin normal to the centre (too
  // far round the sphere for this chart).
  bool to_chart(const Eigen::Vector3d &p, Eigen::Vector2d &x) const;
  Eigen::Vector3d to_sphere(const Eigen::Vector2d &x) const;
  Eigen::Vector3d centre, u1, u2;
};

} // namespace meromorph
