// Loops over the machine's cores.
//
// In:  a count and a body. Out: `parallel_for`: body(i) has run for every i in [0, count), split
//      into one contiguous block per thread of the job's team (OpenMP, static schedule; the team's
//      size: common/job_threads.h), or in order on this thread where the count is small, the team
//      is one thread or OpenMP is missing. The body must not throw and must write only
//      what belongs to its own index; sums over the results are left to the caller, in index
//      order, so that they come out the same on any number of cores. `chunked_sum`: body(begin,
//      end) returns the sum over one chunk of [0, count); the chunks (fixed, whatever the number
//      of cores) run over the cores and their sums are added in chunk order: the same result on
//      any machine, from one pass over the items however many sums each item feeds.
//      `parallel_select`: the indices i in [0, count) where test(i) holds, in increasing order.
//      `parallel_smallest`: the k smallest of key(i) over i in [0, count), as (key, i) pairs in
//      increasing order (equal keys by index): each chunk's k smallest, merged.
//      `parallel_for_with`: body(i, state) for every i, dynamically scheduled, `state` each
//      thread's own, made by make_state() once per thread (a scratch copy to change and restore).
//      `parallel_pair`: first() and second() at once on OpenMP's threads (kept between calls,
//      each with the memory its allocations left: a thread made per call starts afresh), one
//      per core; an exception of either is thrown here once both are done.
//      `while_threads_start`: work() runs on this thread while OpenMP starts the other threads of
//      its team, which the loops after it then find running (its exception is thrown here).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <utility>
#include <vector>

#if defined(_OPENMP)
#include <omp.h>
#endif

#include "common/job_threads.h"

namespace meromorph {

// Below this many items the threads' start costs more than the work: waking the team costs
// microseconds on an idle machine and milliseconds where the other core is busy, and most loops
// here do a fraction of a microsecond per item (a 12.5k-vertex genus-0 map opened 146 regions
// with 4096, 27 with this).
constexpr std::size_t parallel_threshold = 16384;

// `threshold`: the least count worth the threads (the default for items of up to a microsecond's
// work each; chunks of many items want fewer).
template <class Body>
void parallel_for(std::size_t count, const Body &body, std::size_t threshold = parallel_threshold) {
#if defined(_OPENMP)
  const int team = job_team_size(); // common/job_threads.h
  if (count >= threshold && team > 1) count_parallel_region();
#pragma omp parallel for schedule(static) if (count >= threshold && team > 1) num_threads(team)
  for (long i = 0; i < long(count); ++i)
    body(std::size_t(i));
#else
  (void)threshold;
  for (std::size_t i = 0; i < count; ++i)
    body(i);
#endif
}

template <class First, class Second> void parallel_pair(const First &first, const Second &second) {
  std::exception_ptr errors[2];
  parallel_for(
      2,
      [&](std::size_t i) {
        try {
          if (i == 0)
            first();
          else
            second();
        } catch (...) {
          errors[i] = std::current_exception();
        }
      },
      2);
  for (const std::exception_ptr &error : errors)
    if (error) std::rethrow_exception(error);
}

// On the two-core machines a new thread starts on the core of the thread that made it and waits
// there until that core gives way or the next scheduler tick: a process's first parallel loop
// waited 0.1 to 12 ms for its second thread. Made while a serial step runs (reading the input),
// its maker giving way at the end, it is there when the loops need it.
template <class Work> void while_threads_start(const Work &work) {
#if defined(_OPENMP)
  std::exception_ptr error;
  std::atomic<int> arrived{1};
  count_parallel_region();
#pragma omp parallel
  {
    if (omp_get_thread_num() == 0) {
      try {
        work();
      } catch (...) {
        error = std::current_exception();
      }
      // A new thread waits on its maker's core until that core gives way (or the next tick):
      // OpenMP's own wait spins without giving way.
      while (arrived.load() < omp_get_num_threads())
        std::this_thread::yield();
    } else {
      ++arrived;
    }
  }
  if (error) std::rethrow_exception(error);
#else
  work();
#endif
}

// Items per chunk of chunked_sum, and the least number of chunks worth a parallel region: a sum
// is often one of many in a row (a step's candidates weighed one after the other), and each
// region wakes the team, which on a machine with other work waits for a core.
constexpr std::size_t sum_chunk = 8192;
constexpr std::size_t sum_chunks_worth_threads = 4;

// Items per block where a chunk's items are stacked as matrix rows for one matrix product: small
// enough (about 100 KiB at 3 rows of 20 columns each) for the heap to hand the same memory back,
// where a chunk's worth would be mapped and cleared afresh by the system every time.
constexpr std::size_t stacked_block = 256;

template <class Sum, class Body>
Sum chunked_sum(std::size_t count, const Sum &zero, const Body &body) {
  const std::size_t chunks = (count + sum_chunk - 1) / sum_chunk;
  std::vector<Sum> partial(chunks, zero);
  parallel_for(
      chunks,
      [&](std::size_t c) {
        partial[c] = body(c * sum_chunk, std::min(count, (c + 1) * sum_chunk));
      },
      sum_chunks_worth_threads);
  Sum total = zero;
  for (const Sum &part : partial)
    total += part;
  return total;
}

template <class Key>
std::vector<std::pair<double, int>> parallel_smallest(std::size_t count, std::size_t k,
                                                      const Key &key) {
  using Items = std::vector<std::pair<double, int>>;
  struct Smallest {
    Items items;
    std::size_t k;
    Smallest &operator+=(const Smallest &other) {
      Items merged(items.size() + other.items.size());
      std::merge(items.begin(), items.end(), other.items.begin(), other.items.end(),
                 merged.begin());
      merged.resize(std::min(merged.size(), k));
      items = std::move(merged);
      return *this;
    }
  };
  return chunked_sum(count, Smallest{{}, k},
                     [&](std::size_t begin, std::size_t end) {
                       Smallest chunk{Items(end - begin), k};
                       for (std::size_t i = begin; i < end; ++i)
                         chunk.items[i - begin] = {key(i), int(i)};
                       const std::size_t kept = std::min(k, chunk.items.size());
                       std::partial_sort(chunk.items.begin(), chunk.items.begin() + long(kept),
                                         chunk.items.end());
                       chunk.items.resize(kept);
                       return chunk;
                     })
      .items;
}

template <class MakeState, class Body>
void parallel_for_with(std::size_t count, const MakeState &make_state, const Body &body) {
#if defined(_OPENMP)
  const int team = job_team_size(); // common/job_threads.h
  if (count >= 2 && team > 1) count_parallel_region();
#pragma omp parallel if (count >= 2 && team > 1) num_threads(team)
  {
    auto state = make_state();
#pragma omp for schedule(dynamic)
    for (long i = 0; i < long(count); ++i)
      body(std::size_t(i), state);
  }
#else
  auto state = make_state();
  for (std::size_t i = 0; i < count; ++i)
    body(i, state);
#endif
}

template <class Test> std::vector<int> parallel_select(std::size_t count, const Test &test) {
  std::vector<char> selected(count);
  parallel_for(count, [&](std::size_t i) { selected[i] = test(i) ? 1 : 0; });
  std::vector<int> out;
  for (std::size_t i = 0; i < count; ++i)
    if (selected[i]) out.push_back(int(i));
  return out;
}

} // namespace meromorph
