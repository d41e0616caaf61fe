// Genus >= 2: the ratio of two holomorphic 1-forms, a meromorphic function of degree 2g - 2.
//
// In:  a mesh, its edges, and the numerator and denominator forms (complex values per edge).
// Out: per face, F = f_numerator / f_denominator from the local coefficients f of f dz + g dzbar
//      (the ratio does not depend on the frame), a sample at the face's centroid; per vertex, the
//      value at the vertex itself: F = a + b z fitted to its faces' samples (z: centroid offsets
//      in the tangent plane, F in a chart of the sphere at their area-weighted mean), a value of
//      the extended plane. Where the fit would extrapolate (more than half the samples' spread
//      from their mean) the mean itself is taken.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "mesh.h"
#include "mesh_edges.h"
#include "sphere_geometry.h"

namespace meromorph {

std::vector<PlaneValue> form_ratio_map(const Mesh &mesh, const MeshEdges &edges,
                                       const Eigen::VectorXcd &numerator,
                                       const Eigen::VectorXcd &denominator);

} // namespace meromorph
