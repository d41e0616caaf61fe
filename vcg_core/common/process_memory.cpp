#include "common/process_memory.h"

#include <cstdlib> // defines __GLIBC__ where glibc is the C library
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#include <unistd.h>
#endif

namespace meromorph {

void tune_process_memory(char **argv) {
#if defined(__GLIBC__)
  const char *given = std::getenv("GLIBC_TUNABLES");
  std::string tunables = given ? given : "";
  if (tunables.find("glibc.malloc.hugetlb") == std::string::npos) {
    tunables += std::string(tunables.empty() ? "" : ":") + "glibc.malloc.hugetlb=1";
    if (setenv("GLIBC_TUNABLES", tunables.c_str(), 1) == 0) execv("/proc/self/exe", argv);
    // The restart failed: the process goes on as it is.
  }
  mallopt(M_MMAP_THRESHOLD, 1 << 30); // arrays below 1 GiB come from the heap, reused when freed
  mallopt(M_TRIM_THRESHOLD, 1 << 30); // the heap's free top is kept up to 1 GiB
  mallopt(M_TOP_PAD, 256 << 20);      // and grown 256 MiB at a time
  // One heap for every thread: the job runs on a worker thread (common/progress.h), whose own
  // arena would take its large arrays from fresh mappings instead of the memory freed here.
  mallopt(M_ARENA_MAX, 1);
#else
  (void)argv;
#endif
}

} // namespace meromorph
