// A map from every vertex of one closed surface to a point of another of the same genus, through
// their conformal images. Genus 0: both are mapped to the sphere (Moebius-centred), the source's
// sphere is aligned with the target's (match/sphere_alignment.h: by landmarks, or by their
// conformal factors), and each source vertex goes to the point of the target whose sphere point
// meets its aligned one. Genus 1: both as flat tori (match/flat_torus.h), the affine map between
// their lattices and its translation (match/torus_alignment.h), and each source vertex goes to
// the target's point at its image.
//
// In:  SOURCE and TARGET meshes (closed, one part, genus 0, 1 or 2; mapped in place, put back
// exactly),
//      landmark pairs (source vertex, target vertex; may be empty), whether to match back too.
// Out: `SurfaceMatch`: per source vertex the target's triangle (in the target's numbering) and
//      the barycentric weights b1, b2 of its second and third corners, and the point; what the
//      alignment was; measured on the matched mesh (SOURCE's triangles on the matched points):
//      landmark residuals, angle error against SOURCE's own angles, folded faces (a matched
//      triangle whose normal points against TARGET's at each of its corners); with `both`, the
//      target's vertices matched back onto SOURCE and how far the round trip source -> target ->
//      source lands from where it started. Distances are relative to the diagonal of the surface
//      they are measured on.
//      Per source triangle, `FaceMatch` (below). Genus 1 also: both reduced moduli and the
//      alignment of the tori.
// Errors: InputError when the genera differ or are above 1, a surface is not one closed part,
//      has no valid map,
//      or a landmark names a vertex that is not there.
#pragma once

#include <array>
#include <complex>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "common/progress.h"
#include "match/sphere_alignment.h"
#include "match/torus_alignment.h"
#include "mesh/mesh.h"

namespace meromorph {

struct MatchedPoints {
  std::vector<int> target_face;          // per vertex: the target's triangle (-1: none)
  std::vector<Eigen::Vector2d> weights;  // b1, b2 of that triangle's second and third corners
  std::vector<Eigen::Vector3d> position; // the point on the target
};

// A source triangle on the target: the target's triangle that holds the image of its centre, and
// per corner the weights of that triangle's corners that give the corner's matched point (projected
// onto its plane; outside [0, 1] where the corner lies on another target triangle). Values given
// per target corner (texture coordinates with seams) are read from one side of a seam for the
// whole triangle.
struct FaceMatch {
  int target_face = -1; // -1: none
  std::array<Eigen::Vector3d, 3> weights{};
};

struct SurfaceMatch {
  std::vector<FaceMatch> faces; // per source triangle (the input's)
  MatchedPoints forward;        // source vertices on the target
  MatchedPoints backward;       // with `both`: target vertices on the source
  SphereAlignment alignment;    // genus 0
  TorusAlignment torus;         // genus 1
  std::complex<double> source_modulus{}, target_modulus{}; // genus 1, reduced
  int genus = 0;
  int unmatched_vertices = 0;
  double landmark_residual_mean = 0, landmark_residual_max = 0; // / target diagonal
  double angle_error_mean_degrees = 0;
  int folded_faces = 0;
  double round_trip_mean = -1, round_trip_max = -1; // / source diagonal; -1 without `both`
  std::vector<std::pair<std::string, double>> timings_ms;
};

struct MatchOptions {
  std::vector<std::pair<int, int>> landmarks;
  bool both = false;
};

SurfaceMatch match_surfaces(Mesh &source, Mesh &target, const MatchOptions &options,
                            const Progress &progress = {});

} // namespace meromorph
