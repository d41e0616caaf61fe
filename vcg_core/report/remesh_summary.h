// The remesh's quality figures in one line of words, as the CLI prints them and the C ABI,
// MeshLab and Blender show them.
//
// In:  the name of the input (a file or an object), its map and the remesh (surface_remesh.h).
// Out: "NAME: remeshed through D layers: V vertices (target T), F faces, Euler characteristic
//      X (input Y); Hausdorff distance A% / B% of the diagonal; angles min ...; folded lifts N"
//      and, where they apply, faces not lifted and the area distortion before and after.
#pragma once

#include <string>

#include "maps/parameterization.h"
#include "remesh/surface_remesh.h"

namespace meromorph {

std::string remesh_summary(const std::string &input, const Parameterization &map,
                           const SurfaceRemesh &remesh);

} // namespace meromorph
