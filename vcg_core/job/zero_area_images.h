// Images for the zero-area faces put back after the map (zero_area_faces.h).
//
// In:  the mesh with its zero-area faces, which of its faces have zero area, which vertices are
//      merged copies (a needle's vertex merged into another for the computation), the branch
//      vertices (they stay), and the sphere position of every vertex (a copy sits on the vertex
//      it was merged into, a cap's middle vertex wherever the map put it).
// Out: the positions moved so that every face's image is positively oriented, zero-area faces
//      included (a needle's image has no area, a cap's middle vertex may sit on or across its
//      long side): per zero-area face, the copy or else the corner with the widest angle moves,
//      with the others of its kind next to it, from where it is towards where Tutte's embedding
//      (each at the mean of its neighbours, in the gnomonic chart of their images) puts it, by
//      the smallest step that orients every face around them. Returns the vertices moved.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"

namespace meromorph {

std::vector<int> orient_zero_area_images(const Mesh &mesh, const std::vector<int> &zero_area_faces,
                                         const std::vector<char> &is_copy,
                                         const std::vector<char> &is_branch,
                                         std::vector<Eigen::Vector3d> &sphere);

} // namespace meromorph
