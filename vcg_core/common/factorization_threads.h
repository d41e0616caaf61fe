// The threads a sparse Cholesky factorization runs with, while an object of this type lives.
//
// In:  the number of unknowns of the factorization. Out: while one or more of these live (in any
//      thread), every OpenMP parallel region, in our code or in a library, runs with a team of
//      one (libgomp keeps the setting for the whole process), and OpenBLAS runs on one thread
//      below `parallel_blas_unknowns` unknowns (common/blas_threads.h); the previous settings
//      come back when the last one goes.
// Why, measured on the two-core machine: Debian 12's CHOLMOD (3.0.14) starts a parallel region
// of a fixed four threads inside every supernode of a numeric factorization, whatever
// OMP_NUM_THREADS says; the waking and waiting of those threads costs more than the supernodes'
// own work: a 200k-vertex Laplacian factors in 0.50 s with a team of one against 0.74 s. (For
// OpenBLAS's second thread: 160k-vertex genus 1, factorization 805 -> 604 ms with one, the
// holomorphic stage 94 -> 44 ms.)
#pragma once

#include "common/blas_threads.h"

namespace meromorph {

class FactorizationThreads {
public:
  explicit FactorizationThreads(long unknowns);
  ~FactorizationThreads();
  FactorizationThreads(const FactorizationThreads &) = delete;
  FactorizationThreads &operator=(const FactorizationThreads &) = delete;

private:
  BlasThreads blas_;
};

} // namespace meromorph
