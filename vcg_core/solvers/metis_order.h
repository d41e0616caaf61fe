// A fill-reducing elimination order by nested dissection (METIS).
//
// In:  the pattern of a symmetric n x n matrix as its lower or its upper triangle compressed by
//      columns (column_start[n + 1], rows; the diagonal may be there or not).
// Out: the order in which to eliminate the unknowns (order[k] = the k-th eliminated), for
//      CHOLMOD as a given permutation: METIS's vertex separator of the whole graph, each half
//      ordered by METIS's nested dissection, the separator last. The same order on every run.
//      Empty where METIS fails (out of memory): the caller orders by other means. On mesh
//      Laplacians its factor holds a third fewer entries than a minimum degree order's and takes
//      a quarter of the arithmetic, but the ordering costs more time than that saves
//      (solvers/laplacian_solver.cpp uses it where memory is short).
#pragma once

#include <vector>

namespace meromorph {

std::vector<int> nested_dissection_order(int size, const int *column_start, const int *rows);

} // namespace meromorph
