#include "solvers/metis_order.h"

#include <metis.h>

#include "mesh/index_lists.h"

namespace meromorph {
namespace {

// A graph as METIS takes it: every edge in both directions, no self-loops (`start` METIS's
// xadj, `items` its adjncy; idx_t is int in Debian's METIS).
using Graph = IndexLists;
static_assert(sizeof(idx_t) == sizeof(int), "METIS built with 32-bit indices");

// The graph of the vertices flagged `keep` (renumbered in increasing order: `kept` lists them).
Graph subgraph(const Graph &graph, const std::vector<char> &keep, std::vector<int> &kept) {
  const size_t n = keep.size();
  std::vector<int> number(n, -1);
  kept.clear();
  for (size_t v = 0; v < n; ++v)
    if (keep[v]) {
      number[v] = int(kept.size());
      kept.push_back(int(v));
    }
  Graph out;
  out.start.reserve(kept.size() + 1);
  out.start.push_back(0);
  for (int v : kept) {
    for (int w : graph[size_t(v)])
      if (number[size_t(w)] >= 0) out.items.push_back(number[size_t(w)]);
    out.start.push_back(int(out.items.size()));
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
  return METIS_NodeND(&n, graph.start.data(), graph.items.data(), nullptr, options, order.data(),
                      position.data()) == METIS_OK;
}

} // namespace

std::vector<int> nested_dissection_order(int size, const int *column_start, const int *rows) {
  Graph graph = IndexLists::grouped(size_t(size), [&](const auto &add) {
    for (int column = 0; column < size; ++column)
      for (int k = column_start[column]; k < column_start[column + 1]; ++k)
        if (rows[k] != column) {
          add(rows[k], column);
          add(column, rows[k]);
        }
  });
  // The first cut: part 0, part 1, 2 for the separator.
  idx_t n = size, separator_size = 0;
  std::vector<idx_t> part(size_t(size), 0);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  if (METIS_ComputeVertexSeparator(&n, graph.start.data(), graph.items.data(), nullptr, options,
                                   &separator_size, part.data()) != METIS_OK)
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
  // One after the other: METIS keeps its random generator's state in globals, and two calls at
  // once raced on it (the order, and with it the map's last digits, changed from run to run).
  std::vector<idx_t> half_order[2];
  for (int side = 0; side < 2; ++side)
    if (!metis_order(halves[side], half_order[side])) return {};
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
