// The settings a job runs with: the heap reservation's estimate (common/process_memory.h), the
// BLAS threads of small and large jobs (common/blas_threads.h) and the OpenMP teams of a
// factorization (common/factorization_threads.h), read back from OpenBLAS and libgomp themselves.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <dlfcn.h>
#include <gtest/gtest.h>
#include <unistd.h>
#if defined(_OPENMP)
#include <omp.h>
#endif

#include "common/blas_threads.h"
#include "common/factorization_threads.h"
#include "common/parallel_for.h"
#include "common/process_memory.h"

namespace meromorph {
namespace {

constexpr size_t mebibyte = size_t(1) << 20;

size_t half_the_memory() {
  return size_t(sysconf(_SC_PHYS_PAGES)) * size_t(sysconf(_SC_PAGESIZE)) / 2;
}

TEST(ProcessSettings, HeapReservationIsAHundredTimesTheLargestInputWithinBounds) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("meromorph_heap_" + std::to_string(getpid()));
  {
    std::ofstream out(file, std::ios::binary);
    const std::string megabyte(mebibyte, 'x');
    for (int k = 0; k < 4; ++k)
      out << megabyte;
  }
  // 4 MiB of input: 400 MiB, above the least reservation (256 MiB).
  EXPECT_EQ(heap_bytes_for_files({file.string(), "no such file", "/"}), 400 * mebibyte);
  // Names that are not regular files count 0: the least reservation.
  EXPECT_EQ(heap_bytes_for_files({"no such file", "/"}), 256 * mebibyte);
  EXPECT_EQ(heap_bytes_for_files({}, 8 * mebibyte), 8 * mebibyte);
  // Never more than half the machine's memory.
  EXPECT_EQ(heap_bytes_for_files({}, size_t(1) << 50), half_the_memory());
  std::filesystem::remove(file);
}

#if defined(MEROMORPH_GLIBC_MALLOC) // (tests/CMakeLists.txt: not under AddressSanitizer)
// The job's arrays start at a 2 MiB boundary, where transparent huge pages can back them whole.
TEST(ProcessSettings, TheReservedHeapStartsAtAHugePageBoundary) {
  tune_process_memory(64 * mebibyte);
  const std::vector<char> array(16 * mebibyte, 1);
  const uintptr_t offset = reinterpret_cast<uintptr_t>(array.data()) % (2 * mebibyte);
  EXPECT_LT(offset, 64 * 1024u) << "(gtest's own small allocations may come first)";
}
#endif

// OpenBLAS's thread setting, from the BLAS that CHOLMOD loaded (Debian's libblas.so.3 is
// OpenBLAS where setup.sh installed it, as on CI).
struct OpenBlas {
  void (*set)(int) = nullptr;
  int (*get)() = nullptr;
};
OpenBlas open_blas() {
  OpenBlas blas;
  for (const char *library : {"libblas.so.3", "libopenblas.so.0"}) {
    void *handle = dlopen(library, RTLD_LAZY | RTLD_NOLOAD);
    if (!handle) continue;
    blas.set = reinterpret_cast<void (*)(int)>(dlsym(handle, "openblas_set_num_threads"));
    blas.get = reinterpret_cast<int (*)()>(dlsym(handle, "openblas_get_num_threads"));
    dlclose(handle);
    if (blas.set && blas.get) return blas;
  }
  return {};
}

TEST(ProcessSettings, SmallJobsRunOpenBlasOnOneThreadAndGiveTheSettingBack) {
  const OpenBlas blas = open_blas();
  ASSERT_TRUE(blas.set && blas.get) << "the BLAS loaded is not OpenBLAS";
  blas.set(2);
  const int before = blas.get(); // 2 where the machine has two cores or more
  ASSERT_GE(before, 1);
  {
    const BlasThreads small(parallel_blas_unknowns - 1);
    EXPECT_EQ(blas.get(), 1);
    {
      const BlasThreads nested(1000);
      EXPECT_EQ(blas.get(), 1);
    }
    EXPECT_EQ(blas.get(), 1); // the outer guard still lives
  }
  EXPECT_EQ(blas.get(), before);
  {
    const BlasThreads large(parallel_blas_unknowns);
    EXPECT_EQ(blas.get(), before);
  }
  EXPECT_EQ(blas.get(), before);
}

size_t threads_of_this_process() {
  size_t count = 0;
  for (const auto &entry : std::filesystem::directory_iterator("/proc/self/task")) {
    (void)entry;
    ++count;
  }
  return count;
}

TEST(ProcessSettings, AProgramOwningItsProcessEndsOpenBlasIdleThreadsWhenASmallJobStarts) {
  const OpenBlas blas = open_blas();
  ASSERT_TRUE(blas.set && blas.get) << "the BLAS loaded is not OpenBLAS";
  blas.set(2); // its worker threads run (the machines this runs on have two cores or more)
  ASSERT_EQ(blas.get(), 2);
  const size_t with_workers = threads_of_this_process();
  {
    const BlasThreads not_owned(1000); // a host's process: its threads are left alone
    EXPECT_EQ(threads_of_this_process(), with_workers);
  }
  own_blas_threads(); // as tune_process_memory does for the CLI and the bench
  {
    const BlasThreads small(1000);
    EXPECT_LT(threads_of_this_process(), with_workers);
    EXPECT_EQ(blas.get(), 1);
  }
  EXPECT_EQ(blas.get(), 1); // left so: no threads started again only to idle until the exit
  EXPECT_LT(threads_of_this_process(), with_workers);
  {
    const BlasThreads large(parallel_blas_unknowns); // a large job takes them back
    EXPECT_EQ(blas.get(), 2);
    {
      const BlasThreads small_inside(1000);
      EXPECT_EQ(blas.get(), 1);
    }
  }
  {
    const BlasThreads small(1000);
    const BlasThreads large_beside(parallel_blas_unknowns); // a small job running keeps one
    EXPECT_EQ(blas.get(), 1);
  }
}

#if defined(_OPENMP) // (built with OpenMP wherever the compiler has it: vcg_core/CMakeLists.txt)
// The serial work runs on this thread while the team starts; the loops after it find the team.
TEST(ProcessSettings, SerialWorkRunsHereWhileTheOtherThreadsStart) {
  const std::thread::id caller = std::this_thread::get_id();
  std::thread::id ran_on;
  int threads_meanwhile = 0;
  while_threads_start([&] {
    ran_on = std::this_thread::get_id();
    threads_meanwhile = omp_get_num_threads();
  });
  EXPECT_EQ(ran_on, caller);
  EXPECT_EQ(threads_meanwhile, omp_get_max_threads()); // (2 on the two-core machines)
  EXPECT_THROW(while_threads_start([] { throw std::runtime_error("unreadable"); }),
               std::runtime_error);
  std::vector<int> doubled(10000);
  parallel_for(doubled.size(), [&](size_t i) { doubled[i] = 2 * int(i); });
  EXPECT_EQ(doubled[9999], 19998);
}

TEST(ProcessSettings, FactorizationsRunOpenMpTeamsOfOneAndGiveTheLevelsBack) {
  const int levels = omp_get_max_active_levels();
  ASSERT_GT(levels, 0);
  {
    const FactorizationThreads factorization(parallel_blas_unknowns * 2);
    EXPECT_EQ(omp_get_max_active_levels(), 0);
    int team = 0;
#pragma omp parallel
    {
#pragma omp single
      team = omp_get_num_threads();
    }
    EXPECT_EQ(team, 1);
  }
  EXPECT_EQ(omp_get_max_active_levels(), levels);
}
#endif

} // namespace
} // namespace meromorph
