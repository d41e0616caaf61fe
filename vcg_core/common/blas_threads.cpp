#include "common/blas_threads.h"

#include <atomic>
#include <mutex>

#include <dlfcn.h>

namespace meromorph {
namespace {

std::mutex guard_mutex;
int serial_guards = 0, threads_before = 0;
std::atomic<bool> process_owned{false};

// OpenBLAS's thread setting, looked up in the BLAS that CHOLMOD loaded (no link-time dependency:
// with another BLAS there is nothing to set). Null where OpenBLAS is not loaded.
struct OpenBlasThreads {
  void (*set)(int) = nullptr;
  int (*get)() = nullptr;
  void (*stop_idle)() = nullptr; // ends the idle threads; OpenBLAS starts them again when needed
  int initial = 1;               // its threads when first looked up, before any guard set them
};

const OpenBlasThreads &open_blas() {
  static const OpenBlasThreads found = [] {
    OpenBlasThreads threads;
    const auto look_up = [&threads](void *handle) {
      threads.set = reinterpret_cast<void (*)(int)>(dlsym(handle, "openblas_set_num_threads"));
      threads.get = reinterpret_cast<int (*)()>(dlsym(handle, "openblas_get_num_threads"));
      threads.stop_idle = reinterpret_cast<void (*)()>(dlsym(handle, "blas_thread_shutdown_"));
      if (!threads.set || !threads.get) threads = {};
      if (threads.get) threads.initial = threads.get();
      return threads.set != nullptr;
    };
    for (const char *library : {"libblas.so.3", "libopenblas.so.0"}) {
      void *handle = dlopen(library, RTLD_LAZY | RTLD_NOLOAD);
      if (!handle) continue;
      const bool found = look_up(handle);
      dlclose(handle); // still loaded: CHOLMOD needs it
      if (found) return threads;
    }
    look_up(RTLD_DEFAULT); // linked into the program itself (the command-line tool), exported
    return threads;
  }();
  return found;
}

} // namespace

void own_blas_threads() {
  process_owned = true;
}

BlasThreads::BlasThreads(long unknowns) : serial_(unknowns < parallel_blas_unknowns) {
  const OpenBlasThreads &blas = open_blas();
  if (!blas.set) return;
  const std::lock_guard<std::mutex> lock(guard_mutex);
  if (!serial_) {
    // A process of our own keeps the setting the last small job left (below): a large job takes
    // the threads back, unless a small one is running.
    if (process_owned && serial_guards == 0 && blas.get() != blas.initial) blas.set(blas.initial);
    return;
  }
  if (serial_guards++ == 0) {
    threads_before = blas.get();
    if (threads_before == 1) return; // (setting it would start the ended threads again)
    blas.set(1);
    // Its threads idle from the load (or the last call) spin for about 0.1 s before they sleep.
    if (blas.stop_idle && process_owned) blas.stop_idle();
  }
}

BlasThreads::~BlasThreads() {
  const OpenBlasThreads &blas = open_blas();
  if (!blas.set || !serial_) return;
  const std::lock_guard<std::mutex> lock(guard_mutex);
  // Setting it back would start the threads again, to spin through the writing of the outputs
  // and be ended at exit: a process of our own leaves that to its next large job.
  if (--serial_guards == 0 && threads_before != 1 && !process_owned) blas.set(threads_before);
}

} // namespace meromorph
