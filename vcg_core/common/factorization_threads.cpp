#include "common/factorization_threads.h"

#include <mutex>

#if defined(_OPENMP)
#include <omp.h>
#endif

namespace meromorph {
namespace {

std::mutex guard_mutex;
int live_guards = 0;
int levels_before = 0;

} // namespace

FactorizationThreads::FactorizationThreads(long unknowns) : blas_(unknowns) {
  const std::lock_guard<std::mutex> lock(guard_mutex);
#if defined(_OPENMP)
  // No parallel region may be active: every team has one thread.
  if (live_guards == 0) {
    levels_before = omp_get_max_active_levels();
    omp_set_max_active_levels(0);
  }
#endif
  ++live_guards;
}

FactorizationThreads::~FactorizationThreads() {
  const std::lock_guard<std::mutex> lock(guard_mutex);
#if defined(_OPENMP)
  if (live_guards == 1) omp_set_max_active_levels(levels_before);
#endif
  --live_guards;
}

} // namespace meromorph
