// A loop over the machine's cores.
//
// In:  a count and a body taking an index. Out: body(i) has run for every i in [0, count), split
//      into one contiguous block per core (OpenMP, static schedule: the same split on every run),
//      or in order on one thread where the count is small or OpenMP is missing. The body must not
//      throw and must write only what belongs to its own index; sums over the results are left
//      to the caller, in index order, so that they come out the same on any number of cores.
#pragma once

#include <cstddef>

namespace meromorph {

// Below this many items the threads' start costs more than the work.
constexpr std::size_t parallel_threshold = 4096;

template <class Body> void parallel_for(std::size_t count, const Body &body) {
#if defined(_OPENMP)
#pragma omp parallel for schedule(static) if (count >= parallel_threshold)
  for (long i = 0; i < long(count); ++i)
    body(std::size_t(i));
#else
  for (std::size_t i = 0; i < count; ++i)
    body(i);
#endif
}

} // namespace meromorph
