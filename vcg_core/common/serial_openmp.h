// OpenMP parallel regions run by one thread while an object of this type lives.
//
// In:  nothing. Out: while one or more of these live (in any thread), every OpenMP parallel
//      region, in our code or in a library, runs with a team of one (libgomp keeps the setting
//      for the whole process); the previous setting comes back when the last one goes.
// Why: Debian 12's CHOLMOD (3.0.14) starts a parallel region of a fixed four threads inside
//      every supernode of a numeric factorization, whatever OMP_NUM_THREADS says. On the two-core
//      machine the waking and waiting of those threads costs more than the supernodes' own work:
//      a 200k-vertex Laplacian factors in 0.50 s with a team of one against 0.74 s (and 3 s
//      of system time for five factorizations against 1.3 s). OpenBLAS's own threads (the dense
//      products of the large supernodes) are not OpenMP's and keep working.
#pragma once

namespace meromorph {

class SerialOpenMP {
public:
  SerialOpenMP();
  ~SerialOpenMP();
  SerialOpenMP(const SerialOpenMP &) = delete;
  SerialOpenMP &operator=(const SerialOpenMP &) = delete;
};

} // namespace meromorph
