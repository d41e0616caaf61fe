// The C library as a guest in its host's process (MeshLab, Blender, Python): linked as it ships
// (libmeromorph.so), a map with and without a progress callback leaves the host's OpenMP settings
// (on the calling thread and on others), OpenBLAS's thread count and the process's threads as
// they were: the library sets nothing process-wide and keeps no thread.
#include <chrono>
#include <cmath>
#include <dirent.h>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <omp.h>

#include "meromorph.h"

// OpenBLAS's own call, where it is the BLAS CHOLMOD loaded (null otherwise).
extern "C" int openblas_get_num_threads(void) __attribute__((weak));

namespace {

int threads_in_process() {
  int count = 0;
  if (DIR *tasks = opendir("/proc/self/task")) {
    while (const dirent *entry = readdir(tasks))
      count += entry->d_name[0] != '.';
    closedir(tasks);
  }
  return count;
}

struct HostSettings {
  int max_active_levels, dynamic, max_threads, blas_threads;
  bool operator==(const HostSettings &o) const {
    return max_active_levels == o.max_active_levels && dynamic == o.dynamic &&
           max_threads == o.max_threads && blas_threads == o.blas_threads;
  }
};

HostSettings settings_here() {
  return {omp_get_max_active_levels(), omp_get_dynamic(), omp_get_max_threads(),
          openblas_get_num_threads ? openblas_get_num_threads() : -1};
}

// A torus of revolution, R = 2, r = 1: positions and triangles.
void torus(int around, int tube, std::vector<double> &xyz, std::vector<int32_t> &triangles) {
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      const double u = 2 * M_PI * i / around, v = 2 * M_PI * j / tube;
      xyz.insert(xyz.end(),
                 {(2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v)});
      const int a = i * tube + j, b = ((i + 1) % around) * tube + j,
                c = ((i + 1) % around) * tube + (j + 1) % tube, d = i * tube + (j + 1) % tube;
      triangles.insert(triangles.end(), {a, b, c, a, c, d});
    }
}

TEST(HostProcess, AMapLeavesTheHostsSettingsAndThreadsAsTheyWere) {
  std::vector<double> xyz;
  std::vector<int32_t> triangles;
  torus(120, 60, xyz, triangles); // 7,200 vertices: large enough for the parallel loops
  omp_set_max_active_levels(3);   // a host's own choices
  omp_set_num_threads(2);
  const HostSettings before = settings_here();
  // What a new thread of the host starts with (OpenMP keeps these settings per thread).
  const auto on_a_new_thread = [] {
    HostSettings seen{};
    std::thread([&] { seen = settings_here(); }).join();
    return seen;
  };
  const HostSettings new_thread_before = on_a_new_thread();
  const int threads_before = threads_in_process();
  for (const bool with_progress : {false, true}) {
    meromorph_options options;
    meromorph_default_options(&options);
    if (with_progress) options.progress = [](double, const char *, void *) -> int { return 1; };
    meromorph_result *result = nullptr;
    ASSERT_EQ(meromorph_parameterize_d(xyz.data(), xyz.size() / 3, triangles.data(),
                                       triangles.size() / 3, &options, &result),
              MEROMORPH_OK)
        << meromorph_last_error();
    EXPECT_EQ(meromorph_degree(result), 2);
    meromorph_result_free(result);
    EXPECT_TRUE(settings_here() == before) << "progress " << with_progress;
    // And a new thread of the host starts as it did before.
    EXPECT_TRUE(on_a_new_thread() == new_thread_before) << "progress " << with_progress;
  }
  // The relayed job's thread (and its OpenMP team) ended with it: no thread is kept.
  int threads_after = threads_in_process();
  for (int wait = 0; wait < 100 && threads_after > threads_before; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    threads_after = threads_in_process();
  }
  // (The calling thread's own OpenMP team, made by the job without a callback, is the host's;
  // LLVM's OpenMP runtime, in the sanitizer build, also keeps a pool of workers for any thread's
  // next team.)
#if defined(__clang__)
  const int runtime_pool = 1;
#else
  const int runtime_pool = 0;
#endif
  EXPECT_LE(threads_after, threads_before + omp_get_max_threads() - 1 + runtime_pool);
}

} // namespace
