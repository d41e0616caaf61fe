// Genus 0: a degree-1 conformal map onto the sphere that folds no triangle.
//
// In:  a closed genus-0 mesh, its edges and cotangent weights, the solver, and the face to puncture
//      (-1: the best-shaped face among those of about median area).
// Out: a value of the extended plane per vertex (the map before projection). Method (Angenent et
// al. 1999, Haker et al. 2000, made
//      fold-free): remove the puncture face; fix its three corners at the images of the simple pole
//      1 / (w - centroid) in the face's own conformal coordinate w; solve L z = 0 at every other
//      vertex for the complex z = u + i v; project inversely stereographically. Cotangent weights
//      that are negative or tiny (non-Delaunay edges) are raised to a small positive floor, which
//      makes every interior vertex a strictly convex combination of its neighbours, so by Tutte's
//      and Floater's theorems the planar map is an embedding onto the convex pole triangle: no
//      face folds, on long thin parts too. The count of raised weights is reported.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"
#include "mesh/prepared_mesh.h"
#include "solvers/laplacian_solver.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {

// The pinned-pole map's factorization, kept for the south-pole step (genus0_correction.h): it
// eliminated `cap` (free vertices) last, so its leading block is the factor of the Laplacian with
// the cap and the puncture face's `corners` pinned (leading_block_solve.h frees the corners).
struct CapLastFactor {
  std::shared_ptr<const LaplacianSolver> solver;
  std::shared_ptr<const Eigen::SparseMatrix<double>> laplacian;
  std::vector<double> weights; // the Laplacian's
  std::vector<int> cap, corners;
};

struct Genus0Map {
  std::vector<PlaneValue> values;
  int pole_face = -1;
  int raised_weights = 0;
  std::vector<double> weights;   // the edge weights solved with (some raised)
  std::vector<int> folded_faces; // in the plane, before projection, among faces doubles resolve
  // The puncture face's corners, then the other vertices in the order the solve eliminated them:
  // an order for the factorizations that follow on the same edges (laplacian_solver.h).
  std::vector<int> elimination_order;
  CapLastFactor cap_last; // where genus0_map was given a cap to eliminate last
};

// Whether some edge's image is shorter than `crowding_ratio` of the largest value: then one
// solve's rounding (relative to the whole map) can reach that edge's size.
constexpr double crowding_ratio = 1e-9;
bool values_crowd(const MeshEdges &edges, const Eigen::VectorXcd &z);

// The harmonic extension of complex values given at `pinned` (the rest ignored) to every other
// vertex: one factorization of the free vertices' Laplacian, two solves; where the values crowd
// (values_crowd), steps of iterative refinement (the residual summed over edge differences, exact
// there), two solves a step. `elimination_order` as in factor_laplacian.
Eigen::VectorXcd harmonic_extension(const Eigen::SparseMatrix<double> &laplacian,
                                    const MeshEdges &edges, const std::vector<double> &weights,
                                    SolverKind solver, const std::vector<int> &pinned,
                                    const Eigen::VectorXcd &fixed, int refinement_steps = 1,
                                    const std::vector<int> &elimination_order = {});

// The same with a solver at hand (V x k in, V x k out, 0 at the pinned vertices).
using ColumnSolve = std::function<Eigen::MatrixXd(const Eigen::MatrixXd &)>;
Eigen::VectorXcd harmonic_extension_by(const ColumnSolve &solve,
                                       const Eigen::SparseMatrix<double> &laplacian,
                                       const MeshEdges &edges, const std::vector<double> &weights,
                                       const Eigen::VectorXcd &fixed, int refinement_steps);

// The puncture face taken when none is asked for: among the faces of about median area, the one
// with the largest smallest angle (the pole's model 1 / w is accurate on a small, round face).
int default_pole_face(const PreparedMesh &prepared);

// Smallest angles closer than this (radians) are a tie, taken by the lower face index: the same
// mesh saved in single precision (PLY floats, whose rounding moves a median face's angles by about
// 3e-5 on a 400k-face mesh) or as text picks the same pole among faces of nearly the same shape.
constexpr double pole_angle_tie = 1e-3;

// Of the faces `eligible` accepts, the one with the largest smallest angle (ties as above); -1
// where there is none.
int best_shaped_face_among(const Mesh &mesh, const std::function<bool(size_t)> &eligible);

// The weights below a floor of 1e-3 of the median positive weight raised to it, where `raise`
// (one flag per edge; empty: all) allows; `raised` counts them.
std::vector<double> positive_weights(const std::vector<double> &weights,
                                     const std::vector<char> &raise, int &raised);

// Marks the vertices within `rings` edges of the marked ones.
void grow_by_rings(const PreparedMesh &prepared, std::vector<char> &marked, int rings);

// Around folded faces: `raise` flags the edges within two rings of their corners, `region` the
// vertices within `local_rings` more, where a map is solved again with those weights raised.
constexpr int local_rings = 10;
void region_around_folds(const PreparedMesh &prepared, const std::vector<int> &folded_faces,
                         std::vector<char> &raise, std::vector<char> &region);

// `raise` (one flag per edge; empty: every edge) says which weights get the positive floor: the
// plain cotangent map is the most conformal, but with negative weights it may fold;
// `folded_faces` lists the faces turned over in the plane, so that a caller can raise the weights
// around them only, and all of them as the last resort.
// With CHOLMOD and `cap_to_eliminate_last` (one flag per vertex) given, the factorization
// eliminates those vertices last and is kept (Genus0Map::cap_last); `elimination_order`, if given,
// is an earlier call's on the same puncture and cap (Genus0Map::elimination_order), not computed
// again.
Genus0Map genus0_map(const PreparedMesh &prepared, SolverKind solver, int pole_face = -1,
                     const std::vector<char> &raise = {},
                     const std::vector<char> &cap_to_eliminate_last = {},
                     const std::vector<int> &elimination_order = {});

// `first` solved again on the whole mesh with the weights of `raise` given the floor, as
// genus0_map would, but with `first`'s kept factor (Genus0Map::cap_last) updated for the few
// changed weights (reweighted_solve.h) instead of a new factorization. Empty where `first` kept
// no factor or the change touches too many vertices. The result keeps no factor of its own.
std::optional<Genus0Map> genus0_map_reweighted(const PreparedMesh &prepared, const Genus0Map &first,
                                               const std::vector<char> &raise);

// `first` with the vertices of `region` (one flag per vertex) solved again with the weights of
// `raise` given the floor, every other vertex and the puncture face's corners kept where `first`
// put them: a Dirichlet problem on the region alone (region_extension.h), assembled and factored
// at the region's size.
Genus0Map genus0_map_again_in(const PreparedMesh &prepared, const Genus0Map &first,
                              const std::vector<char> &raise, const std::vector<char> &region);

} // namespace meromorph
