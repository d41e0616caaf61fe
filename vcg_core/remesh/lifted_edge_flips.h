// Edge flips on a lifted sphere: where two lifted faces make a poor pair (the corners opposite
// their common side add up to more than 180 degrees on the surface) or one of them folds, their
// common side is replaced by the other diagonal, as isotropic remeshers do.
//
// In:  the mapped surface (path_lifting.h), a lifted sphere (layered_sphere_lift.h) and the most
//      passes over its sides.
// Out: the lifted sphere with such sides flipped where the flip keeps both new faces positively
//      oriented on the sphere (so the sphere mesh stays an embedding of each sheet and the genus
//      and sheets are untouched), folds neither on the surface, adds no side that is there
//      already and leaves every vertex four faces or more; a pair that does not fold must also
//      bend no more than it did (plus 10 degrees: the new side stays near the surface) and gain
//      in smallest corner angle. Returns the number of flips.
#pragma once

#include "remesh/layered_sphere_lift.h"

namespace meromorph {

int flip_lifted_edges(const MappedSurface &surface, int passes, LiftedSphere &lifted);

} // namespace meromorph
