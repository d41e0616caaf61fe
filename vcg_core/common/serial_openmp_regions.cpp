#include "common/serial_openmp_regions.h"

#include <atomic>

namespace meromorph {
namespace {

std::atomic<bool> every_region_to_libgomp{false};

} // namespace

void hand_every_openmp_region_to_libgomp() {
  every_region_to_libgomp = true;
}

} // namespace meromorph

// Only with GCC's OpenMP, whose entry point this is (MEROMORPH_SERIAL_OPENMP_REGIONS, set by the
// build where that holds).
#if defined(MEROMORPH_SERIAL_OPENMP_REGIONS)
#include <dlfcn.h>
#include <omp.h>

extern "C" void GOMP_parallel(void (*body)(void *), void *data, unsigned threads, unsigned flags) {
  using Parallel = void (*)(void (*)(void *), void *, unsigned, unsigned);
  static const Parallel libgomp_parallel =
      reinterpret_cast<Parallel>(dlsym(RTLD_NEXT, "GOMP_parallel"));
  const bool one_thread = threads == 1 || (threads == 0 && omp_get_max_threads() == 1) ||
                          omp_get_active_level() >= omp_get_max_active_levels();
  if (!libgomp_parallel ||
      (one_thread && !meromorph::every_region_to_libgomp.load(std::memory_order_relaxed))) {
    body(data);
    return;
  }
  libgomp_parallel(body, data, threads, flags);
}
#endif
