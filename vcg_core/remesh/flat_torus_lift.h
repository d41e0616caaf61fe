// Genus 1: the remesh's samples taken on the flat torus instead of the sphere.
//
// In:  the mapped surface of a genus-1 part (path_lifting.h), its flat coordinate z per vertex
//      (genus1_map.h: P(z) is the map; z is defined up to the lattice), the lattice's reduced
//      basis (w1, w2; Im(w2 / w1) > 0), the layer of each face, the local degree of each vertex
//      (>= 2 at the map's four branch points) and the number of samples wanted.
// Out: a `LiftedSphere` (layered_sphere_lift.h) whose vertices are the points of a regular
//      triangular grid of the flat torus (n x m points, n and m even, spaced a = w1 / n and
//      c = (w2 + k w1) / m with c / a nearest e^(i pi / 3), so the triangles are nearly
//      equilateral in the flat metric and, the map z being conformal, nearly equilateral on the
//      surface up to its scale), each located in the surface face whose flat triangle holds it and
//      interpolated there; per vertex its sphere value (the map as written, linear on the face and
//      projected), layer and surface point. The map P(z) is the layered sphere's two sheets, so the
//      grid is a triangulation of the layered sphere with no crowding: the P-function shrinks a
//      thin torus's far side exponentially, a sphere mesh samples it with slivers that fold. The
//      grid point nearest each branch vertex is moved onto it (local degree kept). Grid faces with
//      a corner over no face (a hole closed for the map) are left out, counted as unlifted.
#pragma once

#include <array>
#include <complex>
#include <vector>

#include "remesh/layered_sphere_lift.h"

namespace meromorph {

LiftedSphere lift_flat_torus(const MappedSurface &surface,
                             const std::vector<std::complex<double>> &flat,
                             const std::array<std::complex<double>, 2> &periods,
                             const std::vector<int> &face_layer,
                             const std::vector<int> &local_degree, long long samples);

} // namespace meromorph
