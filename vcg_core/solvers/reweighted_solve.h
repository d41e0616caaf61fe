// Solves after a few edge weights changed, with the factor from before (Woodbury).
//
// In:  a factor of the cotangent Laplacian with the weights `before` and some vertices pinned
//      (laplacian_solver.h), those pinned vertices, the edges, and the weights `after`, which
//      differ from `before` on a few edges.
// Out: solves of the Laplacian with the weights `after`, the same vertices pinned, as from a
//      factorization of its own: with B the free ends of the changed edges and D the change of
//      the Laplacian on them, (A + E D E^T)^-1 b = y - Z (I + D Z_B)^-1 D y_B, y = A^-1 b,
//      Z = A^-1 E (|B| solves, once). `usable()` is false where more than `most_vertices`
//      vertices are touched (then a new factorization is cheaper).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "mesh/mesh_edges.h"
#include "solvers/laplacian_solver.h"

namespace meromorph {

class ReweightedSolve {
public:
  ReweightedSolve(const LaplacianSolver &factor, int vertex_count, const std::vector<int> &pinned,
                  const MeshEdges &edges, const std::vector<double> &before,
                  const std::vector<double> &after, int most_vertices = 64);
  bool usable() const { return usable_; }
  // V x k in, V x k out (0 at the pinned vertices).
  Eigen::MatrixXd solve_columns(const Eigen::MatrixXd &right_hand_sides) const;

private:
  const LaplacianSolver &factor_;
  bool usable_ = true;
  std::vector<int> touched_;                         // B
  Eigen::MatrixXd change_;                           // D, |B| x |B|
  Eigen::MatrixXd touched_solved_;                   // Z, V x |B|
  Eigen::PartialPivLU<Eigen::MatrixXd> capacitance_; // I + D Z_B
};

} // namespace meromorph
