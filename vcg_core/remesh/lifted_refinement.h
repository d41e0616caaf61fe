// Evening out a lifted sphere: where a conformal map shrinks the surface (long parts, the far
// side of a torus), a uniform sphere's triangles lift large; they are split there.
//
// In:  the mapped surface (path_lifting.h), a lifted sphere (layered_sphere_lift.h), the target
//      face area on the surface and the most rounds of splitting.
// Out: the lifted sphere refined, each round: every face of more than 2.5 times the target area
//      split 1-to-4 at the midpoints of its sides on the sphere (a face with two sides split gets
//      its third split too; a face with one side split is halved), each new vertex lifted from a
//      side's end that is no branch vertex along the sphere arc to the midpoint, so it lies on
//      the surface in that end's sheet. Each lifted copy is refined on its own (the sheets need
//      not agree). Folded lifts recounted.
#pragma once

#include "remesh/layered_sphere_lift.h"

namespace meromorph {

void refine_lifted_sphere(const MappedSurface &surface, double target_face_area, int rounds,
                          LiftedSphere &lifted);

// Surface area of each lifted face.
std::vector<double> lifted_face_areas(const LiftedSphere &lifted);

} // namespace meromorph
