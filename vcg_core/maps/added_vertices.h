// Where a map turns faces over, the sides to cut; and where the cut vertices lie on the mesh.
//
// In:  a mesh and a map on it (its sphere positions, branch flags and folded faces as measured);
//      for places, the mesh cut (edge_splitting.h, its vertices first) with, per face, the mesh's
//      face it is part of.
// Out: `sides_to_cut`: the side opposite every corner at a branch point of local degree e that is
//      (about) 180 / e degrees or more (the map multiplies the angle there: such a face turns over
//      or flattens whatever the values), and per folded face one side: the side opposite its
//      branch point when it has one, else its longest side; each side once.
//      `places_on`: per vertex of the cut mesh after the mesh's own, the mesh's face it lies on,
//      its barycentric coordinates there (b1, b2: of the face's second and third corners) and its
//      position among `positions` (the mesh's vertex positions in the caller's unit).
#pragma once

#include <array>
#include <vector>

#include "maps/parameterization.h"
#include "mesh/edge_splitting.h"
#include "mesh/mesh.h"

namespace meromorph {

std::vector<std::array<int, 2>> sides_to_cut(const Mesh &mesh, const Parameterization &map);

std::vector<AddedVertex> places_on(const Mesh &mesh, const std::vector<Point3> &positions,
                                   const MeshArrays &cut, const std::vector<int> &face_source);

} // namespace meromorph
