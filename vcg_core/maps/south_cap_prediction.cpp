#include "maps/south_cap_prediction.h"

#include <array>

#include <Eigen/SparseCore>

#include "maps/genus0_correction.h"
#include "mesh/index_lists.h"
#include "solvers/laplacian_solver.h"

namespace meromorph {
namespace {

// Coarse graphs have at most this many nodes; below it, the mesh's own graph is used.
constexpr int coarse_nodes = 4096;
// Fewer free nodes than this: no prediction.
constexpr int least_free_nodes = 64;

struct WeightedGraph {
  int nodes = 0;
  std::vector<std::array<int, 2>> edges;
  std::vector<double> weights;
  std::vector<Eigen::Vector3d> position_sums; // of the vertices in each node
  std::vector<int> vertex_counts;

  IndexLists edges_at_node() const {
    return IndexLists::grouped(size_t(nodes), [&](auto &&emit) {
      for (size_t e = 0; e < edges.size(); ++e)
        for (int end : edges[e])
          emit(end, int(e));
    });
  }
};

// Each node's aggregate: a node whose neighbours are all untaken takes them; the nodes left join
// the aggregate of their most strongly connected neighbour.
std::vector<int> aggregates(const WeightedGraph &graph, int &count) {
  const IndexLists at = graph.edges_at_node();
  auto other = [&](int e, int node) {
    return graph.edges[size_t(e)][0] == node ? graph.edges[size_t(e)][1]
                                             : graph.edges[size_t(e)][0];
  };
  std::vector<int> of(size_t(graph.nodes), -1);
  count = 0;
  for (int v = 0; v < graph.nodes; ++v) {
    if (of[size_t(v)] >= 0) continue;
    bool free = true;
    for (int e : at[size_t(v)])
      free &= of[size_t(other(e, v))] < 0;
    if (!free) continue;
    of[size_t(v)] = count;
    for (int e : at[size_t(v)])
      of[size_t(other(e, v))] = count;
    ++count;
  }
  std::vector<int> joined = of;
  for (int v = 0; v < graph.nodes; ++v) {
    if (of[size_t(v)] >= 0) continue;
    double strongest = -1;
    for (int e : at[size_t(v)])
      if (of[size_t(other(e, v))] >= 0 && graph.weights[size_t(e)] > strongest) {
        strongest = graph.weights[size_t(e)];
        joined[size_t(v)] = of[size_t(other(e, v))];
      }
    if (joined[size_t(v)] < 0) joined[size_t(v)] = count++;
  }
  return joined;
}

// The graph of the aggregates: weights between two aggregates summed, edges inside one dropped.
WeightedGraph coarsened(const WeightedGraph &graph, const std::vector<int> &of, int count) {
  WeightedGraph out;
  out.nodes = count;
  out.position_sums.assign(size_t(count), Eigen::Vector3d::Zero());
  out.vertex_counts.assign(size_t(count), 0);
  for (int v = 0; v < graph.nodes; ++v) {
    out.position_sums[size_t(of[size_t(v)])] += graph.position_sums[size_t(v)];
    out.vertex_counts[size_t(of[size_t(v)])] += graph.vertex_counts[size_t(v)];
  }
  // Edges grouped by their lower aggregate, merged with a marker per higher one.
  const IndexLists by_low = IndexLists::grouped(size_t(count), [&](auto &&emit) {
    for (size_t e = 0; e < graph.edges.size(); ++e) {
      const int a = of[size_t(graph.edges[e][0])], b = of[size_t(graph.edges[e][1])];
      if (a != b) emit(std::min(a, b), int(e));
    }
  });
  std::vector<int> slot(size_t(count), -1);
  for (int low = 0; low < count; ++low) {
    const size_t first = out.edges.size();
    for (int e : by_low[size_t(low)]) {
      const int a = of[size_t(graph.edges[size_t(e)][0])],
                b = of[size_t(graph.edges[size_t(e)][1])];
      const int high = std::max(a, b);
      if (slot[size_t(high)] < 0 || size_t(slot[size_t(high)]) < first) {
        slot[size_t(high)] = int(out.edges.size());
        out.edges.push_back({low, high});
        out.weights.push_back(0);
      }
      out.weights[size_t(slot[size_t(high)])] += graph.weights[size_t(e)];
    }
  }
  return out;
}

// The mesh's graph coarsened into aggregates until at most coarse_nodes are left; `node_of` says
// each vertex's node.
WeightedGraph coarse_graph(const PreparedMesh &prepared, const std::vector<double> &weights,
                           std::vector<int> &node_of) {
  const Mesh &mesh = prepared.mesh;
  const int n = int(mesh.vert.size());
  WeightedGraph graph;
  graph.nodes = n;
  graph.edges = prepared.edges.vertices;
  graph.weights = weights;
  graph.position_sums.resize(size_t(n));
  graph.vertex_counts.assign(size_t(n), 1);
  for (int v = 0; v < n; ++v)
    graph.position_sums[size_t(v)] = mesh.vert[size_t(v)].cP().ToEigenVector<Eigen::Vector3d>();
  node_of.resize(size_t(n));
  for (int v = 0; v < n; ++v)
    node_of[size_t(v)] = v;
  while (graph.nodes > coarse_nodes) {
    int count = 0;
    const std::vector<int> of = aggregates(graph, count);
    if (count == graph.nodes) break;
    graph = coarsened(graph, of, count);
    for (int &node : node_of)
      node = of[size_t(node)];
  }
  return graph;
}

// The pole on the coarse graph: 2 for the nodes holding the pole face's corners (left out), 1 for
// their neighbours (pinned), 0 elsewhere.
std::vector<char> pole_flags(const WeightedGraph &graph, const std::vector<int> &node_of,
                             const std::array<int, 3> &corners) {
  std::vector<char> flag(size_t(graph.nodes), 0);
  for (int c : corners)
    flag[size_t(node_of[size_t(c)])] = 2;
  for (const std::array<int, 2> &edge : graph.edges)
    for (int k = 0; k < 2; ++k)
      if (flag[size_t(edge[size_t(k)])] == 2 && !flag[size_t(edge[size_t(1 - k)])])
        flag[size_t(edge[size_t(1 - k)])] = 1;
  return flag;
}

// The pinned nodes' values: 1 / w of their mean position w in the pole face's plane, about its
// centroid.
Eigen::MatrixXd pinned_values(const Mesh &mesh, const WeightedGraph &graph,
                              const std::vector<char> &flag, const std::array<int, 3> &corners) {
  const Eigen::Vector3d p0 = mesh.vert[size_t(corners[0])].cP().ToEigenVector<Eigen::Vector3d>();
  const Eigen::Vector3d p1 = mesh.vert[size_t(corners[1])].cP().ToEigenVector<Eigen::Vector3d>();
  const Eigen::Vector3d p2 = mesh.vert[size_t(corners[2])].cP().ToEigenVector<Eigen::Vector3d>();
  const Eigen::Vector3d centroid = (p0 + p1 + p2) / 3.0;
  const Eigen::Vector3d e1 = (p1 - p0).normalized();
  const Eigen::Vector3d e2 = (p1 - p0).cross(p2 - p0).cross(p1 - p0).normalized();
  Eigen::MatrixXd given = Eigen::MatrixXd::Zero(graph.nodes, 2);
  for (int node = 0; node < graph.nodes; ++node) {
    if (flag[size_t(node)] != 1) continue;
    const Eigen::Vector3d d =
        graph.position_sums[size_t(node)] / graph.vertex_counts[size_t(node)] - centroid;
    const Complex w(d.dot(e1), d.dot(e2));
    const Complex z = std::abs(w) > 0 ? 1.0 / w : Complex(0, 0);
    given(node, 0) = z.real();
    given(node, 1) = z.imag();
  }
  return given;
}

Eigen::SparseMatrix<double> graph_laplacian(const WeightedGraph &graph) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(4 * graph.edges.size() + size_t(graph.nodes));
  for (size_t e = 0; e < graph.edges.size(); ++e) {
    const int a = graph.edges[e][0], b = graph.edges[e][1];
    const double w = graph.weights[e];
    entries.push_back({a, b, -w});
    entries.push_back({b, a, -w});
    entries.push_back({a, a, w});
    entries.push_back({b, b, w});
  }
  Eigen::SparseMatrix<double> laplacian(graph.nodes, graph.nodes);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  return laplacian;
}

} // namespace

std::vector<char> predicted_south_cap(const PreparedMesh &prepared,
                                      const std::vector<double> &positive_weights, int pole_face) {
  const Mesh &mesh = prepared.mesh;
  const int n = int(mesh.vert.size());
  std::vector<int> node_of;
  const WeightedGraph graph = coarse_graph(prepared, positive_weights, node_of);
  // Not coarsened: predicting would cost the factorization it saves.
  if (graph.nodes == n) return {};

  // The pole: the nodes holding the pole face's corners left out, their neighbours pinned.
  const std::array<int, 3> &corners = prepared.incidence.corners[size_t(pole_face)];
  const std::vector<char> pinned_flag = pole_flags(graph, node_of, corners);
  std::vector<int> pinned;
  for (int node = 0; node < graph.nodes; ++node)
    if (pinned_flag[size_t(node)]) pinned.push_back(node);
  if (graph.nodes - int(pinned.size()) < least_free_nodes) return {};

  const Eigen::MatrixXd given = pinned_values(mesh, graph, pinned_flag, corners);
  const Eigen::SparseMatrix<double> laplacian = graph_laplacian(graph);
  const Eigen::MatrixXd coarse = factor_laplacian(laplacian, SolverKind::cholmod, pinned)
                                     ->solve_columns(-(laplacian * given)) +
                                 given;
  std::vector<PlaneValue> values(static_cast<size_t>(n));
  for (int v = 0; v < n; ++v) {
    const int node = node_of[size_t(v)];
    values[size_t(v)] = {Complex(coarse(node, 0), coarse(node, 1)), pinned_flag[size_t(node)] == 2};
  }
  std::vector<char> cap(static_cast<size_t>(n), 0);
  for (int v : south_cap(values))
    cap[size_t(v)] = 1;
  return cap;
}

} // namespace meromorph
