// Relaxing a lifted sphere on the surface: each vertex moved toward the middle of its faces,
// the way isotropic remeshers smooth tangentially, but through the sphere, so the vertex stays on
// the surface in its own sheet and the sphere mesh stays an embedding.
//
// In:  the mapped surface (path_lifting.h), the layer of each of its faces, a lifted sphere
//      (layered_sphere_lift.h, possibly refined) and the number of rounds.
// Out: the lifted sphere with its vertices moved, its connectivity unchanged: per round, each
//      vertex that is no branch vertex nor on a hole's boundary gets the sphere value whose lift is
//      nearest the area-weighted mean of its faces' centroids on the surface (the map's inverse
//      taken linear over the one-ring, fitted to the neighbours), lifted along the sphere arc from
//      where it was. A move is kept only where every face around the vertex stays positively
//      oriented on the sphere, no face around it folds on the surface that did not already, and the
//      smallest corner angle around it does not fall (or stays above 35 degrees); otherwise it is
//      halved, up to three times. Sphere value, surface point, position and layer move together;
//      folded lifts recounted.
#pragma once

#include <vector>

#include "remesh/layered_sphere_lift.h"

namespace meromorph {

void relax_lifted_sphere(const MappedSurface &surface, const std::vector<int> &face_layer,
                         int rounds, LiftedSphere &lifted);

} // namespace meromorph
