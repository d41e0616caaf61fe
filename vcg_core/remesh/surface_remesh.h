// The remesh job: a new triangulation of the surface sampled through its layered sphere.
//
// In:  the surface as parameterized (parameterize_surface's input) and its map (valid: a
//      branched cover on every part; made with `area_correct` for an even sampling), options (the
//      sphere's frequency from `resolution` N as k = 2^N, or from a vertex target, by default the
//      input's vertex count, shared among the parts by their vertex counts; whether to even out
//      the triangles' sizes) and progress.
// Out: `SurfaceRemesh`: per part, a geodesic sphere (geodesic_sphere.h) with the part's branch
//      values on vertices, lifted to the part (layered_sphere_lift.h; a part of genus 1: a
//      regular grid of its flat torus instead, flat_torus_lift.h, its sample count scaled so that
//      the refined result holds about the target), evened out where its
//      triangles lift large or lie over much of the surface (lifted_refinement.h, covered_area.h:
//      long parts the map shrinks get their share; the frequency chosen so the result holds about
//      the target), then rounds of edge flips (lifted_edge_flips.h) and tangential relaxation
//      through the sphere (lifted_relaxation.h) for the triangles' shapes; the parts' lifts
//      together as one mesh (part by part), with per vertex its layer, sphere value, local degree
//      at branch vertices (0 elsewhere) and part; per part its frequency, degree and ramification;
//      the target vertex count (what the lifted spheres hold when everything lifts); what did not
//      lift and the folded lifts; the quality against the input (remesh_quality.h); the regions
//      short of samples (sample_coverage.h: under a quarter of their fair share, 0.5% of the
//      area or more; one part without non-manifold splits; only without evening out, which fills
//      them). A hole closed for the map is a gap on the sphere: its faces do not lift, and the
//      remesh has a hole there too. With an edge length or a largest error instead of a vertex
//      target, the target follows from it (below).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "common/progress.h"
#include "maps/parameterization.h"
#include "mesh/mesh.h"
#include "remesh/remesh_quality.h"
#include "remesh/sample_coverage.h"

namespace meromorph {

// The largest vertex target (the command line's and the C library's bound).
constexpr long long max_remesh_vertices = 2000000000LL;

struct RemeshOptions {
  int resolution = -1;     // N >= 0: frequency 2^N; -1: from the vertex target
  long long vertices = -1; // the vertex target; -1: the input's vertex count
  // Instead of a vertex target (> 0 when given): the edge length of equilateral triangles that
  // tile the surface (the target is the count such triangles need), or the largest Hausdorff
  // distance both ways over the bounding-box diagonal (the fewest vertices found to meet it:
  // remeshed at targets scaled by how far each try lands, up to `max_error_tries`).
  double edge_length = -1, max_error = -1;
  int max_error_tries = 6;
  double sparse_below = 0.25;
  // Split lifted faces larger than the target (lifted_refinement.h); with a vertex target the
  // sphere's frequency is lowered so that the refined result holds about the target.
  bool even_out = true;
  // Rounds of edge flips and tangential relaxation after evening out (lifted_edge_flips.h,
  // lifted_relaxation.h).
  int relaxation_rounds = 12;
};

struct RemeshPart {
  int frequency = 0, degree = 0, ramification = 0;
  long long target_vertices = 0;
};

struct SurfaceRemesh {
  Mesh mesh;
  std::vector<int> layer, local_degree, part;
  std::vector<Eigen::Vector3d> sphere;
  std::vector<RemeshPart> parts;
  long long target_vertices = 0;
  int unlifted_faces = 0, unclosed_faces = 0, folded_lifts = 0;
  RemeshQuality quality;
  std::vector<SparseRegion> sparse_regions;
};

// `out` must be new (a vcglib mesh cannot be returned by value). Throws InputError when the lift of
// a closed part does not close (faces whose edge lifts do not meet), naming the nearest two branch
// values, and when no try meets `max_error` (naming the closest).
void remesh_through_sphere(const Mesh &input, const Parameterization &map,
                           const RemeshOptions &options, const Progress &progress,
                           SurfaceRemesh &out);

} // namespace meromorph
