// A closed surface from an implicit function: marching cubes, then isotropic remeshing.
//
// In:  a scalar field (negative inside, positive outside, zero on the surface), a box that holds
//      the surface with room to spare, a voxel size, and whether to remesh.
// Out: `mesh`, the zero level set extracted by vcglib's marching cubes (topologically consistent
//      tables), oriented outward, cleaned of degenerate faces and, when asked, isotropically
//      remeshed by vcglib to edge length about `voxel` so that triangles are well shaped.
#pragma once

#include <functional>

#include "mesh/mesh.h"

namespace meromorph {

using ScalarField = std::function<double(const Point3 &)>;

void extract_isosurface(const ScalarField &field, const vcg::Box3d &box, double voxel, Mesh &mesh,
                        bool remesh = true);

} // namespace meromorph
