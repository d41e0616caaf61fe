// A fill-reducing elimination order by nested dissection (METIS), over both cores.
//
// In:  the pattern of a symmetric n x n matrix as its lower triangle compressed by columns
//      (column_start[n + 1], rows; the diagonal may be there or not).
// Out: the order in which to eliminate the unknowns (order[k] = the k-th eliminated), for
//      CHOLMOD as a given permutation: METIS's vertex separator of the whole graph, each half
//      ordered by METIS's nested dissection on a core of its own, the separator last. Empty where
//      METIS fails (out of memory): the caller orders by other means. On mesh Laplacians from
//      about half a million unknowns on, its factor holds a third fewer entries than a minimum
//      degree order's and takes a quarter of the arithmetic; below that the ordering costs more
//      than it saves.
#pragma once

#include <vector>

namespace meromorph {

std::vector<int> nested_dissection_order(int size, const int *column_start, const int *rows);

} // namespace meromorph
