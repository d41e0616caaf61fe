// The threads a job runs with: serial work while the team starts (common/parallel_for.h), each
// thread's own scratch (common/thread_scratch.h), and a factorization's OpenMP teams of one on
// its own thread only (solvers/factorization_threads.h), read back from libgomp itself.
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#if defined(_OPENMP)
#include <omp.h>
#endif

#include "common/job_threads.h"
#include "common/parallel_for.h"
#include "common/thread_scratch.h"
#include "solvers/factorization_threads.h"

namespace meromorph {
namespace {

#if defined(_OPENMP) // (built with OpenMP wherever the compiler has it: vcg_core/CMakeLists.txt)
// Each thread of a team has its own scratch per tag, kept from one use to the next.
TEST(ProcessSettings, ThreadScratchIsEachThreadsOwn) {
  struct First;
  struct Second;
  const int threads = 2;
  std::vector<size_t> kept(threads, 0), second(threads, 1);
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    std::vector<int> &scratch = thread_scratch<First, std::vector<int>>();
    scratch.assign(size_t(1000 * (t + 1)), t);
  }
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    const std::vector<int> &scratch = thread_scratch<First, std::vector<int>>();
    kept[size_t(t)] = scratch.size() == size_t(1000 * (t + 1)) && scratch.front() == t;
    second[size_t(t)] = thread_scratch<Second, std::vector<int>>().size();
  }
  for (int t = 0; t < threads; ++t) {
    EXPECT_EQ(kept[size_t(t)], 1u) << "thread " << t;
    EXPECT_EQ(second[size_t(t)], 0u) << "thread " << t; // another tag, another array
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

// The threads of one region that asks for four, as CHOLMOD's supernodes do.
int team_asking_for_four() {
  int team = 0;
#pragma omp parallel num_threads(4)
  {
#pragma omp single
    team = omp_get_num_threads();
  }
  return team;
}

// While a factorization runs, the regions of its thread get one thread even where they ask for
// four; a region of another thread at the same time gets its four (nothing process-wide
// changed: a host's threads keep their teams); afterwards this thread's settings are back.
TEST(ProcessSettings, FactorizationsRunTeamsOfOneOnTheirOwnThreadOnly) {
  const int levels = omp_get_max_active_levels(), dynamic = omp_get_dynamic(),
            threads = omp_get_max_threads();
  std::atomic<int> phase{0};
  int other_team = 0;
  std::thread other([&] {
    while (phase.load() == 0)
      std::this_thread::yield();
    other_team = team_asking_for_four();
    phase = 2;
  });
  {
    const FactorizationThreads factorization;
    EXPECT_EQ(team_asking_for_four(), 1);
    phase = 1;
    while (phase.load() != 2)
      std::this_thread::yield();
    EXPECT_EQ(team_asking_for_four(), 1);
  }
  other.join();
  EXPECT_EQ(other_team, 4);
  EXPECT_EQ(team_asking_for_four(), 4);
  EXPECT_EQ(omp_get_max_active_levels(), levels);
  EXPECT_EQ(omp_get_dynamic(), dynamic);
  EXPECT_EQ(omp_get_max_threads(), threads);
}
#endif

// The rule: the usable CPUs (capped by OpenMP's limit) less the other processes' runnable
// threads, at least one; with nothing known of the others, every usable CPU.
TEST(ProcessSettings, TheJobsTeamLeavesCoresBusyElsewhereToTheirWork) {
  EXPECT_EQ(team_size_for(2, 2, 1, 1), 2); // only this thread runs
  EXPECT_EQ(team_size_for(2, 2, 3, 2), 1); // one other process busy
  EXPECT_EQ(team_size_for(2, 2, 5, 1), 1); // more than the cores: still one
  EXPECT_EQ(team_size_for(8, 8, 4, 1), 5);
  EXPECT_EQ(team_size_for(8, 3, 1, 1), 3); // OMP_NUM_THREADS=3
  EXPECT_EQ(team_size_for(2, 2, -1, 1), 2);
}

#if defined(_OPENMP)
// With every core kept busy by other processes, a job's loops run on its own thread alone; a
// JobThreads made inside keeps the outer one's team; after the job, loops get OpenMP's maximum.
TEST(ProcessSettings, BesideBusyProcessesAJobRunsOnOneThread) {
  std::vector<pid_t> busy;
  for (int k = 0; k < omp_get_num_procs(); ++k) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      alarm(60);
      volatile double x = 1;
      while (true)
        x = x * 1.0000001 + 1e-9;
    }
    busy.push_back(child);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(50)); // they run
  std::atomic<int> widest{0};
  {
    const JobThreads job;
    EXPECT_EQ(job.threads(), 1);
    {
      const JobThreads inner;
      EXPECT_EQ(inner.threads(), 1);
    }
    parallel_for(100000, [&](size_t) {
      int expected = widest.load();
      while (omp_get_num_threads() > expected &&
             !widest.compare_exchange_weak(expected, omp_get_num_threads())) {
      }
    });
  }
  for (pid_t child : busy) {
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
  }
  EXPECT_EQ(widest.load(), 1);
  EXPECT_EQ(job_team_size(), omp_get_max_threads());
}
#endif

} // namespace
} // namespace meromorph
