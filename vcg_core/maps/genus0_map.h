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

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "forms/laplacian_solver.h"
#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"
#include "mesh/prepared_mesh.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {

struct Genus0Map {
  std::vector<PlaneValue> values;
  int puncture_face = -1;
  int raised_weights = 0;
  std::vector<double> weights;   // the edge weights solved with (some raised)
  std::vector<int> folded_faces; // in the plane, before projection, among faces doubles resolve
  // The puncture face's corners, then the other vertices in the order the solve eliminated them:
  // an order for the factorizations that follow on the same edges (laplacian_solver.h).
  std::vector<int> elimination_order;
};

// Whether some edge's image is shorter than `crowding_ratio` of the largest value: then one
// solve's rounding (relative to the whole map) can reach that edge's size.
constexpr double crowding_ratio = 1e-9;
bool values_crowd(const MeshEdges &edges, const Eigen::VectorXcd &z);

// The harmonic extension of complex values given at `pinned` (the rest ignored) to every other
// vertex: one factorization of the free vertices' Laplacian, two solves; where the values crowd
// (values_crowd), steps of iterative refinement (the residual summed over edge differences, exact
// there), two solves a step. `elimination_order` as in factor_laplacian; where `used_order` is
// given, the order the factorization used goes there.
Eigen::VectorXcd harmonic_extension(const Eigen::SparseMatrix<double> &laplacian,
                                    const MeshEdges &edges, const std::vector<double> &weights,
                                    SolverKind solver, const std::vector<int> &pinned,
                                    const Eigen::VectorXcd &fixed, int refinement_steps = 1,
                                    const std::vector<int> &elimination_order = {},
                                    std::vector<int> *used_order = nullptr);

// `raise` (one flag per edge; empty: every edge) says which weights get the positive floor: the
// plain cotangent map is the most conformal, but with negative weights it may fold;
// `folded_faces` lists the faces turned over in the plane, so that a caller can raise the weights
// around them only, and all of them as the last resort.
Genus0Map genus0_map(const PreparedMesh &prepared, SolverKind solver, int puncture_face = -1,
                     const std::vector<char> &raise = {});

// `first` with the vertices of `region` (one flag per vertex) solved again with the weights of
// `raise` given the floor, every other vertex and the puncture face's corners kept where `first`
// put them: a Dirichlet problem on the region alone, so its factorization is the region's size.
Genus0Map genus0_map_again_in(const PreparedMesh &prepared, SolverKind solver,
                              const Genus0Map &first, const std::vector<char> &raise,
                              const std::vector<char> &region);

} // namespace meromorph
