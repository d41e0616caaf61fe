// The settings a job runs with: the heap reservation's estimate (common/process_memory.h), the
// BLAS threads of small and large jobs (common/blas_threads.h), the OpenMP teams of a
// factorization (common/factorization_threads.h) and the regions of one thread
// (common/serial_openmp_regions.h), read back from OpenBLAS and libgomp themselves, and the
// threads' scratch arrays released between jobs (common/thread_scratch.h).
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
#include "common/serial_openmp_regions.h"
#include "common/thread_scratch.h"

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
// Each thread of a team has its own scratch per tag, kept from one use to the next; releasing
// the team's scratch empties every thread's, and the next use starts afresh.
TEST(ProcessSettings, ThreadScratchIsEachThreadsOwnAndTheTeamsIsReleasedAtOnce) {
  struct First;
  struct Second;
  const int threads = 2;
  std::vector<size_t> kept(threads, 0), released(threads, 1), second(threads, 1);
  auto on_each_thread = [&](auto body) {
#if defined(_OPENMP)
#pragma omp parallel num_threads(threads)
    body(omp_get_thread_num());
#else
    body(0);
#endif
  };
  on_each_thread([&](int t) {
    std::vector<int> &scratch = thread_scratch<First, std::vector<int>>();
    scratch.assign(size_t(1000 * (t + 1)), t);
  });
  on_each_thread([&](int t) {
    const std::vector<int> &scratch = thread_scratch<First, std::vector<int>>();
    kept[size_t(t)] = scratch.size() == size_t(1000 * (t + 1)) && scratch.front() == t;
    second[size_t(t)] = thread_scratch<Second, std::vector<int>>().size();
  });
  release_team_scratch();
  on_each_thread(
      [&](int t) { released[size_t(t)] = thread_scratch<First, std::vector<int>>().capacity(); });
#if defined(_OPENMP)
  const int ran = threads;
#else
  const int ran = 1;
#endif
  for (int t = 0; t < ran; ++t) {
    EXPECT_EQ(kept[size_t(t)], 1u) << "thread " << t;
    EXPECT_EQ(second[size_t(t)], 0u) << "thread " << t; // another tag, another array
    EXPECT_EQ(released[size_t(t)], 0u) << "thread " << t;
  }
}

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

// What one `#pragma omp parallel` saw.
struct RegionSeen {
  int level = -1, threads = 0;
  std::vector<char> thread_ran;
};

RegionSeen one_region(bool parallel) {
  RegionSeen seen;
  seen.thread_ran.assign(8, 0);
#pragma omp parallel if (parallel) num_threads(2)
  {
#pragma omp single
    {
      seen.level = omp_get_level();
      seen.threads = omp_get_num_threads();
    }
    seen.thread_ran[size_t(omp_get_thread_num())] = 1; // (each thread its own byte)
  }
  return seen;
}

// The tests link common/serial_openmp_regions.cpp as the command-line tool does: a region that
// can only have one thread is a plain call (no team: the nesting level stays 0), a team of two
// still gets its two threads, and after hand_every_openmp_region_to_libgomp libgomp makes every
// team (level 1 inside, even for one thread). Without GCC's OpenMP (the sanitizer builds) every
// region is libgomp's or the compiler's own.
TEST(ProcessSettings, RegionsOfOneThreadAreCallsAndTeamsStillGetTheirThreads) {
  const RegionSeen team = one_region(true);
  EXPECT_EQ(team.level, 1);
  EXPECT_EQ(team.threads, 2);
  EXPECT_TRUE(team.thread_ran[0] && team.thread_ran[1]);
  const RegionSeen alone = one_region(false);
  EXPECT_EQ(alone.threads, 1);
  EXPECT_TRUE(alone.thread_ran[0]);
  RegionSeen in_factorization;
  {
    const FactorizationThreads factorization(parallel_blas_unknowns * 2);
    in_factorization = one_region(true);
  }
  EXPECT_EQ(in_factorization.threads, 1);
#if defined(MEROMORPH_SERIAL_OPENMP_REGIONS)
  EXPECT_EQ(alone.level, 0);
  EXPECT_EQ(in_factorization.level, 0);
#endif
  // A loop below the threads' threshold, as plain calls, and one above it, as a team.
  std::vector<int> squares(5000);
  parallel_for(100, [&](size_t i) { squares[i] = int(i * i); });
  parallel_for(squares.size(), [&](size_t i) { squares[i] = int(i * i); });
  EXPECT_EQ(squares[99], 9801);
  EXPECT_EQ(squares[4999], 24990001);
}

// (Its own process under ctest: every test is run alone.)
TEST(ProcessSettings, EveryRegionGoesToLibgompOnceHandedOver) {
  hand_every_openmp_region_to_libgomp();
  const RegionSeen alone = one_region(false);
  EXPECT_EQ(alone.level, 1);
  EXPECT_EQ(alone.threads, 1);
  EXPECT_EQ(one_region(true).threads, 2);
}
#endif

} // namespace
} // namespace meromorph
