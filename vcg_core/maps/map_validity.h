// Whether a written map is a valid branched cover, and what a user can do when it is not.
//
// In:  the options and the map as measured (degree, Riemann-Hurwitz, folded and collapsed faces
//      from its quality); for the advice also the input's vertex positions (places are given in
//      its coordinates) and the mesh at the unit scale the map was computed at.
// Out: `invalid_reasons`: what keeps the map from being valid (the expected degree 1, 2 or
//      2g - 2, or less with a chosen form pair; Riemann-Hurwitz; faces turned over, with their
//      indices; faces shrunk below double precision said first when they are the cause); empty
//      when it is valid. `invalid_map_advice`: the likely causes this mesh and map show, each with
//      its remedy (common/remedy.h).
#pragma once

#include <string>
#include <vector>

#include "maps/parameterization.h"
#include "mesh/mesh.h"

namespace meromorph {

std::vector<std::string> invalid_reasons(const ParameterizeOptions &options,
                                         const Parameterization &map);

std::vector<Advice> invalid_map_advice(const std::vector<Point3> &input_positions, const Mesh &mesh,
                                       const ParameterizeOptions &options,
                                       const Parameterization &map);

} // namespace meromorph
