// Genus >= 2: the ratio of two holomorphic 1-forms, a meromorphic function of degree 2g - 2.
//
// In:  a prepared mesh, and the numerator's and denominator's dz coefficients per face (f of
//      f dz + g dzbar: form_pairs.h ratio_dz, holomorphic_forms.h dz_coefficients).
// Out: the value of F = numerator / denominator at every vertex, a value of the extended plane.
//      Per face, the ratio of the forms' holomorphic coefficients (which drops the discrete
//      forms' anti-holomorphic error) is a sample of F at the centroid. The
//      vertex values are solved for globally, in two charts (with s the median of |F| over the
//      vertices' first guesses, F where |F| < 1.6 s, 1 / F where |F| > s / 1.6: half the mesh
//      each, solved at once, one per core, and blended on the sphere between s / 1.25 and
//      1.25 s, inside both): the samples are
//      fitted by least squares, weighted by face area in the sphere's metric, together with the
//      conformal energy of the piecewise-linear map (Dirichlet energy minus signed image area: zero
//      where a face's image is similar to the face). A per-vertex fit would differentiate the
//      forms' face-to-face noise, which on needle-ridden triangulations (raw marching cubes, scans)
//      exceeds what a piecewise-linear map tolerates; the energy keeps the values of neighbouring
//      vertices consistent, so such meshes map as conformally as remeshed ones.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"
#include "mesh/prepared_mesh.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {

// The numerator's and denominator's dz coefficients per face, in that order.
using RatioDz = std::array<std::vector<Complex>, 2>;

// How the charts are solved: conjugate gradients to the relative residual `tolerance` (1e-6
// against 1e-7: 10% to 20% fewer steps, the mean angle error the same to 1e-4 degrees on six
// generated genus-5 to -10 meshes with needles or raw marching cubes; 1e-7 against 1e-10 had
// halved the steps, the same to 1e-6 degrees on the genus-2 and -5 bench meshes), from the first
// guesses or from `start` (per vertex: an earlier solve of the same forms, as it returned them).
// A screening solve (to 1e-3: a quarter of the steps) gives the same crowded faces and the same
// image area to a face or two (the pair search's figures, form_pair_search.h); the map kept is
// solved on from there (RatioMap).
struct RatioSolve {
  double tolerance = 1e-6;
  const std::vector<PlaneValue> *start = nullptr;
};
constexpr double screening_tolerance = 1e-3;

std::vector<PlaneValue> form_ratio_map(const PreparedMesh &prepared, RatioDz dz,
                                       const RatioSolve &how = {});

// The same, solved in passes: `advance(tolerance)` goes on from where the last pass stopped (a
// screening pass and then the full one take the steps of the full one alone and end at the same
// values: solvers/hermitian_cg.h), `values(tolerance)` advances and returns the map; `steps()` the
// most conjugate gradient steps a chart has taken so far. Holds both charts' systems (their
// matrices, preconditioners and the solves' vectors) until it goes.
class RatioMap {
public:
  RatioMap(const PreparedMesh &prepared, RatioDz dz,
           const std::vector<PlaneValue> *start = nullptr);
  RatioMap(RatioMap &&) noexcept;
  RatioMap &operator=(RatioMap &&) noexcept;
  ~RatioMap();
  void advance(double tolerance);
  std::vector<PlaneValue> values(double tolerance);
  int steps() const;

private:
  struct Charts;
  std::unique_ptr<Charts> charts_;
};

// A forecast of the map's crowding before anything is solved: the faces whose first guess (each
// vertex at the mean on the sphere of its faces' samples, as the charts start from) spans more
// than a chord of 1 (a quarter of the sphere), where a zero and a pole of F fall close together.
int guessed_crowding(const PreparedMesh &prepared, const RatioDz &dz);

// The faces whose image (points on the unit sphere per vertex) spans a chord above 1.
int crowded_faces(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere);

} // namespace meromorph
