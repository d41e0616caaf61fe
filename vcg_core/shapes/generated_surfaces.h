// The project's own test surfaces, deterministic: spheres, tori of revolution (whose conformal
// modulus is known exactly) and closed surfaces of any genus.
//
// In:  shape parameters (below); all lengths in model units.
// Out: a closed, connected, consistently and outward oriented triangle mesh, compact.
#pragma once

#include "mesh/mesh.h"

namespace meromorph {

// Icosphere: an icosahedron subdivided `subdivisions` times and projected on the sphere;
// 10 * 4^s + 2 vertices.
void make_icosphere(Mesh &mesh, int subdivisions, double radius = 1.0);

// Torus of revolution around the z axis, radii R > r (exact modulus i sqrt(R^2 - r^2) / r),
// as a regular grid of `major_segments` x `minor_segments` quads split into triangles.
void make_grid_torus(Mesh &mesh, double major_radius, double minor_radius, int major_segments,
                     int minor_segments);

// The same torus of revolution triangulated by marching cubes and isotropic remeshing, with
// about `resolution` edges around the minor circle: a different, irregular triangulation.
// With `remesh` false, marching cubes' own triangles are kept (obtuse and needle-shaped ones).
void make_implicit_torus(Mesh &mesh, double major_radius, double minor_radius, int resolution,
                         bool remesh = true);

// A closed surface of genus `genus` (0..): `genus` rings of tubes of different sizes along a gently
// bending row, each blended with the next (no symmetry: for genus >= 3 not hyperelliptic); genus 0
// is a sphere. `resolution` is about the number of edges across one ring.
void make_genus_surface(Mesh &mesh, int genus, int resolution, bool remesh = true);

// Genus 0 with long thin parts: a ball with `tentacles` tubes of radius 0.12 reaching `length`
// from its centre in well-spread directions, blended in (marching cubes + isotropic remeshing).
// The hard case for conformal maps to the sphere: thin parts shrink exponentially. With `hole`,
// the ball has a hole through it (genus 1, a figure with long limbs) and the tentacles leave the
// ring around it.
void make_tentacle_blob(Mesh &mesh, int tentacles, double length, int resolution,
                        bool hole = false);

// What scans and exporters do to a triangulation, on the same surface: splits a `fraction` of
// the edges (chosen by a hash of their vertex indices, the same on every machine, at most one per
// face) at a point 0.2% to 1% of the way along them (vcglib's RefineE); every split leaves two
// needles with angles down to about 0.05 degrees and their obtuse partners (up to about 150).
// The shape does not change.
void inject_needles(Mesh &mesh, double fraction);

// Flat midpoint subdivision, `steps` times: every edge split at its midpoint and every face into
// four (vcglib's Refine): the same surface, with 4^steps times the faces.
void subdivide_flat(Mesh &mesh, int steps);

} // namespace meromorph
