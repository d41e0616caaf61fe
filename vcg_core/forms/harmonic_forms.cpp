#include "forms/harmonic_forms.h"

#include "common/parallel_for.h"

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

std::vector<Eigen::VectorXd>
harmonic_forms(const std::vector<Eigen::SparseVector<double>> &closed_forms, int vertex_count,
               const MeshEdges &edges, const std::vector<double> &weights,
               std::unique_ptr<LaplacianSolver> solver) {
  // One pass over the factor for all the forms' potentials.
  Eigen::MatrixXd potentials;
  {
    Eigen::MatrixXd divergences = Eigen::MatrixXd::Zero(vertex_count, long(closed_forms.size()));
    for (size_t k = 0; k < closed_forms.size(); ++k)
      for (Eigen::SparseVector<double>::InnerIterator it(closed_forms[k]); it; ++it) {
        const long e = it.index();
        divergences(edges.vertices[size_t(e)][1], long(k)) += weights[size_t(e)] * it.value();
        divergences(edges.vertices[size_t(e)][0], long(k)) -= weights[size_t(e)] * it.value();
      }
    potentials = solver->solve_columns_releasing(std::move(divergences));
  }
  solver.reset();
  std::vector<Eigen::VectorXd> harmonic;
  for (size_t k = 0; k < closed_forms.size(); ++k) {
    Eigen::VectorXd h = closed_forms[k]; // dense from here
    const auto potential = potentials.col(long(k));
    parallel_for(size_t(edges.edge_count()), [&](size_t e) {
      h[long(e)] -= potential[edges.vertices[e][1]] - potential[edges.vertices[e][0]];
    });
    harmonic.push_back(std::move(h));
  }
  return harmonic;
}

} // namespace meromorph
