#include "common/process_memory.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib> // defines __GLIBC__ where glibc is the C library
#include <filesystem>
#include <string>
#include <system_error>

#include "common/blas_threads.h"

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace meromorph {
namespace {

constexpr size_t bytes_per_file_byte = 100;
constexpr uintptr_t huge_page = uintptr_t(2) << 20; // a transparent huge page (x86-64)

size_t physical_memory() {
#if defined(__GLIBC__)
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0) return size_t(pages) * size_t(page);
#endif
  return 0;
}

} // namespace

size_t heap_bytes_for_files(const std::vector<std::string> &paths, size_t at_least) {
  size_t largest = 0;
  for (const std::string &path : paths) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) continue;
    const auto size = std::filesystem::file_size(path, error);
    if (!error) largest = std::max(largest, size_t(size));
  }
  size_t bytes = std::max(at_least, largest * bytes_per_file_byte);
  if (const size_t memory = physical_memory()) bytes = std::min(bytes, memory / 2);
  return bytes;
}

void tune_process_memory(size_t expected_bytes) {
  own_blas_threads(); // (common/blas_threads.h: this process is ours)
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 1 << 30); // arrays below 1 GiB come from the heap
  mallopt(M_ARENA_MAX, 1); // one heap for every thread (a worker thread's own arena would take
                           // its large arrays from fresh mappings, not the memory freed here)
  const char *given = std::getenv("GLIBC_TUNABLES");
  const bool user_chose =
      given && std::string(given).find("glibc.malloc.hugetlb") != std::string::npos;
  mallopt(M_TRIM_THRESHOLD, -1); // the heap's free top is never handed back: the job reuses it
  mallopt(M_TOP_PAD, 256 << 20); // and grows it 256 MiB at a time
  if (user_chose || expected_bytes == 0) return;
  // Huge pages cover only whole 2 MiB blocks of the address space: the heap's free top is moved
  // up to the next boundary (at the end) by an allocation kept for good (address space only, and
  // one page of it touched), so that the job's arrays start at one. Below it, up to 2 MiB of
  // ordinary pages came one fault at a time: about 400 faults of 12 microseconds each on a
  // 4k-vertex map.
  const uintptr_t free_top_start = reinterpret_cast<uintptr_t>(sbrk(0)) - mallinfo2().keepcost;
  const uintptr_t to_boundary = (huge_page - free_top_start % huge_page) % huge_page;
  // The heap grown by the reservation, at most 1 GiB at a time (mallopt takes an int): requests
  // just above its free top with that much padding, each freed again (kept: no trimming).
  char *const before = static_cast<char *>(sbrk(0));
  if (before == reinterpret_cast<char *>(-1)) return;
  const size_t step = size_t(1) << 30;
  mallopt(M_MMAP_MAX, 0); // the requests above the mapping threshold too come from the heap
  for (size_t grown = 0; grown < expected_bytes;) {
    mallopt(M_TOP_PAD, int(std::min(step, expected_bytes - grown)));
    void *grow = malloc(mallinfo2().keepcost + 4096);
    free(grow);
    char *const now = static_cast<char *>(sbrk(0));
    if (grow == nullptr || now <= before + grown) break; // the heap could not grow (limits)
    grown = size_t(now - before);
  }
  mallopt(M_TOP_PAD, 256 << 20);
  const uintptr_t page = uintptr_t(sysconf(_SC_PAGESIZE));
  const uintptr_t start = (free_top_start + to_boundary + page - 1) / page * page;
  const uintptr_t end = reinterpret_cast<uintptr_t>(sbrk(0)) / page * page;
  if (end > start) madvise(reinterpret_cast<void *>(start), end - start, MADV_HUGEPAGE);
  // After the advice: the free top's header, written at the boundary, is the first touch there.
  constexpr uintptr_t chunk_header = 2 * sizeof(size_t);
  if (to_boundary > 2 * chunk_header) {
    static void *volatile kept; // (volatile: an allocation never read may be left out)
    kept = malloc(to_boundary - chunk_header);
  }
  mallopt(M_MMAP_MAX, 65536); // glibc's default
#else
  (void)expected_bytes;
#endif
}

void advise_huge_pages(void *data, size_t bytes) {
#if defined(__GLIBC__)
  const uintptr_t start =
      (reinterpret_cast<uintptr_t>(data) + huge_page - 1) / huge_page * huge_page;
  const uintptr_t end = (reinterpret_cast<uintptr_t>(data) + bytes) / huge_page * huge_page;
  if (end > start) madvise(reinterpret_cast<void *>(start), end - start, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

} // namespace meromorph
