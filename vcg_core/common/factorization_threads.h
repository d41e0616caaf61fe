// The threads a sparse Cholesky factorization runs with, while an object of this type lives.
//
// In:  the number of unknowns of the factorization. Out: while one or more of these live (in any
//      thread), every OpenMP parallel region, in our code or in a library, runs with a team of
//      one (libgomp keeps the setting for the whole process), and OpenBLAS (where it is the BLAS
//      loaded) runs on one thread if every living guard's system has fewer than
//      `parallel_blas_unknowns` unknowns; the previous settings come back when the last one goes.
// Why, measured on the two-core machine:
//  - Debian 12's CHOLMOD (3.0.14) starts a parallel region of a fixed four threads inside every
//    supernode of a numeric factorization, whatever OMP_NUM_THREADS says; the waking and waiting
//    of those threads costs more than the supernodes' own work: a 200k-vertex Laplacian factors
//    in 0.50 s with a team of one against 0.74 s.
//  - OpenBLAS's second thread (the dense products of the large supernodes) gains about 10% at
//    800k unknowns but loses below a few hundred thousand: its first use maps and clears its own
//    buffers, and after every call it spins for a while on the core our per-face loops need
//    (160k-vertex genus 1: factorization 805 -> 604 ms, the holomorphic stage 94 -> 44 ms).
#pragma once

namespace meromorph {

constexpr long parallel_blas_unknowns = 300000;

class FactorizationThreads {
public:
  explicit FactorizationThreads(long unknowns);
  ~FactorizationThreads();
  FactorizationThreads(const FactorizationThreads &) = delete;
  FactorizationThreads &operator=(const FactorizationThreads &) = delete;

private:
  bool serial_blas_;
};

} // namespace meromorph
