#include "common/process_memory.h"

#include <cstdlib> // defines __GLIBC__ where glibc is the C library

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace meromorph {

void keep_freed_memory_for_reuse() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 1 << 30); // arrays below 1 GiB come from the heap, reused when freed
  mallopt(M_TRIM_THRESHOLD, 1 << 30); // the heap's free top is kept up to 1 GiB
  mallopt(M_TOP_PAD, 256 << 20);      // and grown 256 MiB at a time
#endif
}

} // namespace meromorph
