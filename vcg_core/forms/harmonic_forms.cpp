#include "forms/harmonic_forms.h"

namespace meromorph {

Eigen::VectorXd weighted_divergence(int vertex_count, const MeshEdges &edges,
                                    const std::vector<double> &weights,
                                    const Eigen::VectorXd &form) {
  Eigen::VectorXd divergence = Eigen::VectorXd::Zero(vertex_count);
  for (int e = 0; e < edges.edge_count(); ++e) {
    divergence[edges.vertices[e][1]] += weights[e] * form[e];
    divergence[edges.vertices[e][0]] -= weights[e] * form[e];
  }
  return divergence;
}

std::vector<Eigen::VectorXd> harmonic_forms(const std::vector<Eigen::VectorXd> &closed_forms,
                                            int vertex_count, const MeshEdges &edges,
                                            const std::vector<double> &weights,
                                            const LaplacianSolver &solver) {
  // One pass over the factor for all the forms' potentials.
  Eigen::MatrixXd divergences(vertex_count, long(closed_forms.size()));
  for (size_t k = 0; k < closed_forms.size(); ++k)
    divergences.col(long(k)) = weighted_divergence(vertex_count, edges, weights, closed_forms[k]);
  const Eigen::MatrixXd potentials = solver.solve_columns(divergences);
  std::vector<Eigen::VectorXd> harmonic;
  for (size_t k = 0; k < closed_forms.size(); ++k) {
    Eigen::VectorXd h = closed_forms[k];
    const auto potential = potentials.col(long(k));
    for (int e = 0; e < edges.edge_count(); ++e)
      h[e] -= potential[edges.vertices[e][1]] - potential[edges.vertices[e][0]];
    harmonic.push_back(std::move(h));
  }
  return harmonic;
}

} // namespace meromorph
