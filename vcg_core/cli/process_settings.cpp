#include "cli/process_settings.h"

#include "common/job_threads.h"

#include <cstdlib> // defines __GLIBC__ where glibc is the C library

#if defined(__GLIBC__)
#include <malloc.h>
#endif

// OpenBLAS's own call, where OpenBLAS is linked (statically into the command-line tool, or
// loaded for CHOLMOD as the system's BLAS); null with another BLAS.
extern "C" void openblas_set_num_threads(int threads) __attribute__((weak));
extern "C" int openblas_get_num_threads(void) __attribute__((weak));

namespace meromorph::cli {

void tune_command_line_process() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 1 << 30); // arrays below 1 GiB come from the heap
  mallopt(M_ARENA_MAX, 1);            // one heap for every thread
  mallopt(M_TRIM_THRESHOLD, -1);      // the heap's free top is never handed back
  mallopt(M_TOP_PAD, 256 << 20);      // and grows 256 MiB at a time
#endif
  tune_blas_for_job(0);
}

void tune_blas_for_job(long vertices) {
  if (!openblas_set_num_threads || !openblas_get_num_threads) return;
  // Only a change is set: OpenBLAS wakes its idle workers on every call, and they then spin
  // (sched_yield) for about 0.1 s beside the job: 50 ms more per map at 40k vertices.
  const int threads = vertices >= parallel_blas_vertices ? free_cpus() : 1;
  if (threads != openblas_get_num_threads()) openblas_set_num_threads(threads);
}

} // namespace meromorph::cli
