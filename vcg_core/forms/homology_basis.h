// A homology basis by tree-cotree (Eppstein 2003) and the closed 1-forms dual to it.
//
// In:  the vertex count and the oriented edges of a closed, oriented, connected triangulation (a
//      mesh's, or an intrinsic one whose edges may join the same two vertices twice).
// Out: `HomologyBasis` with 2g primal loops (each a list of edges with the direction it is walked:
//      +1 along the edge's direction, -1 against) and 2g closed 1-forms omega_j, +-1 on the edges
//      that dual loop j crosses and 0 elsewhere, such that the integral of omega_j along primal
//      loop i is +-delta_ij. Both spanning trees are breadth-first from vertex 0 / face 0, so the
//      basis depends on the connectivity only (the same after any rigid motion or scale).
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"

namespace meromorph {

struct HomologyBasis {
  int genus = 0;
  std::vector<std::vector<std::pair<int, int>>> primal_loops; // (edge, +1 / -1)
  // Closed 1-forms, nonzero only on the edges their dual loop crosses (a few thousand of
  // millions): sparse, as the harmonic forms made from them are not.
  std::vector<Eigen::SparseVector<double>> dual_forms;
  std::vector<int> generator_edges; // edge in neither tree, per loop
};

HomologyBasis tree_cotree(int vertex_count, const MeshEdges &edges);

// Integral of a 1-form along a loop.
double integrate(const Eigen::VectorXd &form, const std::vector<std::pair<int, int>> &loop);
double integrate(const Eigen::SparseVector<double> &form,
                 const std::vector<std::pair<int, int>> &loop);

} // namespace meromorph
