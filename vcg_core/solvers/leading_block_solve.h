// A Dirichlet problem solved with another one's factor: its leading block, bordered.
//
// In:  a factor of the cotangent Laplacian with some vertices pinned (laplacian_solver.h), that
//      Laplacian, how many of the factor's last eliminated vertices are pinned here too, and a few
//      vertices the factor pinned that are free here (`freed`, e.g. a puncture face's corners).
// Out: solves of the Laplacian at the vertices free here, 0 at the pinned ones, as from a
//      factorization of its own. The leading block's solves (no new factorization) with the
//      freed vertices joined by their Schur complement: the leading block's solves of their
//      columns ride along with the first right-hand sides (one pass over the factor), later ones
//      cost one leading-block solve each. Not for two threads at once.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solvers/laplacian_solver.h"

namespace meromorph {

class LeadingBlockSolve {
public:
  LeadingBlockSolve(const LaplacianSolver &factor, const Eigen::SparseMatrix<double> &laplacian,
                    int last_count, std::vector<int> freed);
  // V x k in, V x k out.
  Eigen::MatrixXd solve_columns(const Eigen::MatrixXd &right_hand_sides) const;

private:
  // The rows of L x at the freed vertices.
  Eigen::MatrixXd laplacian_at_freed(const Eigen::MatrixXd &x) const;

  const LaplacianSolver &factor_;
  const Eigen::SparseMatrix<double> &laplacian_;
  int last_count_;
  std::vector<int> freed_;
  mutable bool bordered_ = false;                // the two below are computed
  mutable Eigen::MatrixXd freed_columns_solved_; // V x m: the leading block's solve of L's columns
  mutable Eigen::MatrixXd schur_inverse_;        // m x m
};

} // namespace meromorph
