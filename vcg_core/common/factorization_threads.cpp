#include "common/factorization_threads.h"

#include <mutex>

#include <dlfcn.h>

#if defined(_OPENMP)
#include <omp.h>
#endif

namespace meromorph {
namespace {

std::mutex guard_mutex;
int live_guards = 0, serial_blas_guards = 0;
int levels_before = 0, blas_threads_before = 0;

// OpenBLAS's thread setting, looked up in the BLAS that CHOLMOD loaded (no link-time dependency:
// with another BLAS there is nothing to set). Null where OpenBLAS is not loaded.
struct OpenBlasThreads {
  void (*set)(int) = nullptr;
  int (*get)() = nullptr;
};

const OpenBlasThreads &open_blas() {
  static const OpenBlasThreads found = [] {
    OpenBlasThreads threads;
    for (const char *library : {"libblas.so.3", "libopenblas.so.0"}) {
      void *handle = dlopen(library, RTLD_LAZY | RTLD_NOLOAD);
      if (!handle) continue;
      threads.set = reinterpret_cast<void (*)(int)>(dlsym(handle, "openblas_set_num_threads"));
      threads.get = reinterpret_cast<int (*)()>(dlsym(handle, "openblas_get_num_threads"));
      dlclose(handle); // still loaded: CHOLMOD needs it
      if (threads.set && threads.get) return threads;
      threads = {};
    }
    return threads;
  }();
  return found;
}

} // namespace

FactorizationThreads::FactorizationThreads(long unknowns)
    : serial_blas_(unknowns < parallel_blas_unknowns) {
  const std::lock_guard<std::mutex> lock(guard_mutex);
#if defined(_OPENMP)
  // No parallel region may be active: every team has one thread.
  if (live_guards == 0) {
    levels_before = omp_get_max_active_levels();
    omp_set_max_active_levels(0);
  }
#endif
  ++live_guards;
  const OpenBlasThreads &blas = open_blas();
  if (!blas.set) return;
  if (serial_blas_ && serial_blas_guards++ == 0) {
    blas_threads_before = blas.get();
    blas.set(1);
  }
}

FactorizationThreads::~FactorizationThreads() {
  const std::lock_guard<std::mutex> lock(guard_mutex);
#if defined(_OPENMP)
  if (live_guards == 1) omp_set_max_active_levels(levels_before);
#endif
  --live_guards;
  const OpenBlasThreads &blas = open_blas();
  if (blas.set && serial_blas_ && --serial_blas_guards == 0) blas.set(blas_threads_before);
}

} // namespace meromorph
