// The threads a sparse Cholesky factorization runs with, while an object of this type lives.
//
// In:  nothing. Out: while it lives, every OpenMP parallel region started from the calling
//      thread (CHOLMOD's, inside a factorization or a solve) runs on that thread alone: the
//      calling thread's max-active-levels setting is 0, put back when it goes. Since OpenMP 5.0
//      that setting belongs to the thread's own data environment (libgomp keeps it per thread
//      from GCC 11 on): regions of other threads, a host's among them, keep their teams, and
//      nothing process-wide changes (tests/test_process_settings.cpp checks both at once).
// Why, measured on the two-core machine: Debian 12's CHOLMOD (3.0.14) asks for a fixed four
// threads (num_threads(4)) in the parallel regions of every large supernode, whatever
// OMP_NUM_THREADS says; on two cores their waking and waiting cost more than the supernodes' own
// work: a 200k-vertex Laplacian factors in 0.50 s with a team of one against 0.74 s. (Dynamic
// teams of one would do the same, but libgomp then reads the load average at every region:
// 20% of a 50k-vertex genus-0 map.)
#pragma once

namespace meromorph {

class FactorizationThreads {
public:
  FactorizationThreads();
  ~FactorizationThreads();
  FactorizationThreads(const FactorizationThreads &) = delete;
  FactorizationThreads &operator=(const FactorizationThreads &) = delete;

private:
  int levels_before_ = 1;
};

} // namespace meromorph
