#include "forms/metis_order.h"

#include <thread>

#include <metis.h>

namespace meromorph {
namespace {

// A graph as METIS takes it: every edge in both directions, no self-loops.
struct Graph {
  std::vector<idx_t> start, neighbours;
};

// The graph of the vertices flagged `keep` (renumbered in increasing order: `kept` lists them).
Graph subgraph(const Graph &graph, const std::vector<char> &keep, std::vector<int> &kept) {
  const size_t n = keep.size();
  std::vector<idx_t> number(n, -1);
  kept.clear();
  for (size_t v = 0; v < n; ++v)
    if (keep[v]) {
      number[v] = idx_t(kept.size());
      kept.push_back(int(v));
    }
  Graph out;
  out.start.reserve(kept.size() + 1);
  out.start.push_back(0);
  for (int v : kept) {
    for (idx_t k = graph.start[size_t(v)]; k < graph.start[size_t(v) + 1]; ++k) {
      const idx_t w = number[size_t(graph.neighbours[size_t(k)])];
      if (w >= 0) out.neighbours.push_back(w);
    }
    out.start.push_back(idx_t(out.neighbours.size()));
  }
  return out;
}

// METIS's nested dissection order of a graph: order[k] = the k-th eliminated vertex.
bool metis_order(Graph &graph, std::vector<idx_t> &order) {
  idx_t n = idx_t(graph.start.size()) - 1;
  order.assign(size_t(n), 0);
  if (n == 0) return true;
  std::vector<idx_t> position(static_cast<size_t>(n));
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  return METIS_NodeND(&n, graph.start.data(), graph.neighbours.data(), nullptr, options,
                      order.data(), position.data()) == METIS_OK;
}

} // namespace

std::vector<int> nested_dissection_order(int size, const int *column_start, const int *rows) {
  Graph graph;
  graph.start.assign(size_t(size) + 1, 0);
  for (int column = 0; column < size; ++column)
    for (int k = column_start[column]; k < column_start[column + 1]; ++k)
      if (rows[k] != column) {
        ++graph.start[size_t(rows[k]) + 1];
        ++graph.start[size_t(column) + 1];
      }
  for (size_t v = 0; v < size_t(size); ++v)
    graph.start[v + 1] += graph.start[v];
  graph.neighbours.resize(size_t(graph.start[size_t(size)]));
  {
    std::vector<idx_t> next(graph.start.begin(), graph.start.end() - 1);
    for (int column = 0; column < size; ++column)
      for (int k = column_start[column]; k < column_start[column + 1]; ++k)
        if (rows[k] != column) {
          graph.neighbours[size_t(next[size_t(rows[k])]++)] = column;
          graph.neighbours[size_t(next[size_t(column)]++)] = rows[k];
        }
  }
  // The first cut: part 0, part 1, 2 for the separator.
  idx_t n = size, separator_size = 0;
  std::vector<idx_t> part(size_t(size), 0);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  if (METIS_ComputeVertexSeparator(&n, graph.start.data(), graph.neighbours.data(), nullptr,
                                   options, &separator_size, part.data()) != METIS_OK)
    return {};
  Graph halves[2];
  std::vector<int> kept[2];
  for (int side = 0; side < 2; ++side) {
    std::vector<char> keep(static_cast<size_t>(size));
    for (size_t v = 0; v < size_t(size); ++v)
      keep[v] = part[v] == side;
    halves[side] = subgraph(graph, keep, kept[side]);
  }
  graph = {};
  std::vector<idx_t> half_order[2];
  bool ordered[2] = {false, false};
  std::thread second([&] { ordered[1] = metis_order(halves[1], half_order[1]); });
  ordered[0] = metis_order(halves[0], half_order[0]);
  second.join();
  if (!ordered[0] || !ordered[1]) return {};
  std::vector<int> order;
  order.reserve(size_t(size));
  for (int side = 0; side < 2; ++side)
    for (idx_t k : half_order[side])
      order.push_back(kept[side][size_t(k)]);
  for (size_t v = 0; v < size_t(size); ++v)
    if (part[v] == 2) order.push_back(int(v));
  return order;
}

} // namespace meromorph
