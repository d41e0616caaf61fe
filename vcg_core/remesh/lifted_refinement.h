// Evening out a lifted sphere: where a conformal map shrinks the surface (long parts, the far
// side of a torus), a uniform sphere's triangles lift large; they are split there.
//
// In:  the mapped surface (path_lifting.h), a lifted sphere (layered_sphere_lift.h), the limits
//      (largest face area, whether folded faces are split) and the most rounds of splitting.
// Out: the lifted sphere refined, each round: every face over a limit (its area, or with the
//      surface's samples given the area of the surface under it) split 1-to-4 at the
//      midpoints of its sides' lifts measured on the surface (a face with two sides split gets its
//      third split too; a face with one side split is halved), each new vertex lifted from a side's
//      end that is no branch vertex along the sphere arc to the midpoint, so it lies on the surface
//      in that end's sheet. Each lifted copy is refined on its own (the sheets need not agree).
//      Along a hole: faces with two corners on the boundary are not split for their size; a side
//      between two boundary vertices gets its middle by a walk from the face's third corner (or
//      where that walk leaves the surface: a new boundary vertex). Folded lifts recounted.
#pragma once

#include "remesh/covered_area.h"
#include "remesh/layered_sphere_lift.h"

namespace meromorph {

// What makes a lifted face split.
struct RefinementLimits {
  double face_area = 1e300; // larger faces are split, or faces over more of the surface
  // The surface's samples, when given (covered_area.h): new, or last located on the lifted sphere
  // to refine (then copied, so that only what the refinement replaces is located again).
  const SampleLocator *samples = nullptr;
  bool folded = false; // and, when set, folded faces
};

void refine_lifted_sphere(const MappedSurface &surface, const RefinementLimits &limits, int rounds,
                          LiftedSphere &lifted);

// Surface area of each lifted face.
std::vector<double> lifted_face_areas(const LiftedSphere &lifted);

} // namespace meromorph
