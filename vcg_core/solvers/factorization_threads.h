// The threads a sparse Cholesky factorization runs with, while an object of this type lives.
//
// In:  nothing. Out: while it lives, every OpenMP parallel region started from the calling
//      thread (CHOLMOD's, inside a factorization or a solve) runs on that thread alone: the
//      calling thread's own OpenMP settings (its dyn-var and nthreads-var, which OpenMP keeps per
//      thread) are set to dynamic teams of at most one thread, and put back when it goes. Regions
//      of other threads, a host's among them, are not affected: nothing process-wide changes.
// Why, measured on the two-core machine: Debian 12's CHOLMOD (3.0.14) asks for a fixed four
// threads (num_threads(4)) in the parallel regions of every large supernode, whatever
// OMP_NUM_THREADS says; on two cores their waking and waiting cost more than the supernodes' own
// work: a 200k-vertex Laplacian factors in 0.50 s with a team of one against 0.74 s. With dynamic
// teams OpenMP may give a region fewer threads than it asks for, at most the nthreads setting.
#pragma once

namespace meromorph {

class FactorizationThreads {
public:
  FactorizationThreads();
  ~FactorizationThreads();
  FactorizationThreads(const FactorizationThreads &) = delete;
  FactorizationThreads &operator=(const FactorizationThreads &) = delete;

private:
  int dynamic_before_ = 0, threads_before_ = 1;
};

} // namespace meromorph
