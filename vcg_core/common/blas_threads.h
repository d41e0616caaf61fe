// The BLAS threads of work on a system of a given size, while an object of this type lives.
//
// In:  the number of unknowns (or vertices) of the work. Out: while one or more of these live (in
//      any thread), OpenBLAS (where it is the BLAS loaded) runs on one thread if every living
//      guard's work has fewer than `parallel_blas_unknowns` unknowns; the previous setting comes
//      back when the last one goes; in a program that owns its process (`own_blas_threads`,
//      called by tune_process_memory), OpenBLAS's idle threads are ended then as well, and the
//      setting stays at one until a guard of a larger job takes the threads back (setting it back
//      would start them again, to spin through the writing of the outputs and be ended at exit).
//      Where another BLAS is loaded, nothing changes.
// Why, measured on the two-core machine: OpenBLAS's second thread gains about 10% in the dense
// products of an 800k-unknown factorization but loses below a few hundred thousand: its first use
// maps and clears its own buffers, and after every call it spins (sched_yield) for a while on the
// core our per-face loops need. With OpenMP's waiting threads spinning too, a 4k-vertex genus-0
// map took 100-130 ms instead of 21-25 ms in a third of the runs when the solves ran with two
// BLAS threads (CHOLMOD's factorization already ran with one; common/factorization_threads.h).
#pragma once

namespace meromorph {

constexpr long parallel_blas_unknowns = 300000;

// For the programs that own their process (the CLI, the bench): a host program (MeshLab,
// Blender) may be running BLAS on another thread, whose threads must not be ended under it.
void own_blas_threads();

class BlasThreads {
public:
  explicit BlasThreads(long unknowns);
  ~BlasThreads();
  BlasThreads(const BlasThreads &) = delete;
  BlasThreads &operator=(const BlasThreads &) = delete;

private:
  bool serial_;
};

} // namespace meromorph
