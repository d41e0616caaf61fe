#include "common/serial_openmp.h"

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

// No parallel region may be active: every team has one thread.
SerialOpenMP::SerialOpenMP() {
#if defined(_OPENMP)
  const std::lock_guard<std::mutex> lock(guard_mutex);
  if (live_guards++ == 0) {
    levels_before = omp_get_max_active_levels();
    omp_set_max_active_levels(0);
  }
#endif
}

SerialOpenMP::~SerialOpenMP() {
#if defined(_OPENMP)
  const std::lock_guard<std::mutex> lock(guard_mutex);
  if (--live_guards == 0) omp_set_max_active_levels(levels_before);
#endif
}

} // namespace meromorph
