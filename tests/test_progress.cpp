// Progress reporting and cancellation.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include "common/errors.h"
#include "common/progress.h"

namespace meromorph {
namespace {

TEST(Progress, RangesMapIntoTheParentAndCancelThrows) {
  std::vector<double> seen;
  bool keep_going = true;
  Progress progress([&](double fraction, const std::string &) {
    seen.push_back(fraction);
    return keep_going;
  });
  progress.report(0.5, "half");
  const Progress second_half = progress.range(0.5, 1.0);
  second_half.report(0.5, "three quarters");
  second_half.range(0.0, 0.5).report(1.0, "still three quarters");
  second_half.report(2.0, "clamped");
  EXPECT_EQ(seen, (std::vector<double>{0.5, 0.75, 0.75, 1.0}));
  keep_going = false;
  EXPECT_THROW(progress.report(0.9, "stop"), Cancelled);
  EXPECT_NO_THROW(Progress().report(0.3, "nobody listens"));
}

// A job on a worker thread: its reports reach the callback on the caller's thread, and while it
// is silent the latest report is handed on again (the bar stays alive in MeshLab and Blender).
TEST(Progress, AJobOnAWorkerReportsOnTheCallersThreadAndKeepsTheBarAlive) {
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::string> stages;
  bool on_caller = true;
  Progress progress([&](double, const std::string &stage) {
    on_caller &= std::this_thread::get_id() == caller;
    stages.push_back(stage);
    return true;
  });
  std::thread::id worker;
  run_reporting(progress, [&](const Progress &relay) {
    worker = std::this_thread::get_id();
    relay.report(0.1, "first");
    std::this_thread::sleep_for(std::chrono::milliseconds(1200)); // silent, like a factorization
    relay.range(0.5, 1.0).report(1.0, "last");
  });
  EXPECT_NE(worker, caller);
  EXPECT_TRUE(on_caller);
  ASSERT_GE(stages.size(), 4u); // "first" handed on again while the job was silent
  EXPECT_EQ(stages.front(), "first");
  EXPECT_EQ(stages.back(), "last");
}

TEST(Progress, ACancelStopsTheJobAtItsNextReportAndAJobsErrorReachesTheCaller) {
  std::atomic<bool> job_unwound{false};
  int calls = 0;
  Progress cancel_at_third([&](double, const std::string &) { return ++calls < 3; });
  EXPECT_THROW(run_reporting(cancel_at_third,
                             [&](const Progress &relay) {
                               try {
                                 for (int step = 0; step < 1000; ++step) {
                                   relay.report(step / 1000.0, "step");
                                   std::this_thread::sleep_for(std::chrono::milliseconds(20));
                                 }
                               } catch (const Cancelled &) {
                                 job_unwound = true;
                                 throw;
                               }
                             }),
               Cancelled);
  EXPECT_TRUE(job_unwound);
  EXPECT_THROW(run_reporting(Progress([](double, const std::string &) { return true; }),
                             [](const Progress &) { throw InputError("bad mesh"); }),
               InputError);
  // Without a callback the job runs on the caller's thread.
  std::thread::id ran_on;
  run_reporting(Progress(), [&](const Progress &) { ran_on = std::this_thread::get_id(); });
  EXPECT_EQ(ran_on, std::this_thread::get_id());
}

// Every relayed job runs on a thread of its own, which ends with it; jobs of two callers at once
// run at once; a child of fork() (Python's multiprocessing, a host's worker processes) runs
// relayed jobs too.
TEST(Progress, EveryRelayedJobRunsOnAThreadOfItsOwn) {
  const Progress progress([](double, const std::string &) { return true; });
  auto job_thread = [&] {
    std::thread::id ran_on;
    run_reporting(progress, [&](const Progress &relay) {
      ran_on = std::this_thread::get_id();
      relay.report(1.0, "done");
    });
    return ran_on;
  };
  EXPECT_NE(job_thread(), std::this_thread::get_id());

  std::atomic<int> running{0};
  std::atomic<bool> both_at_once{false};
  std::thread::id outer_thread, inner_thread;
  auto meet = [&](std::thread::id &ran_on) {
    ran_on = std::this_thread::get_id();
    ++running;
    for (int wait = 0; wait < 500 && running < 2; ++wait)
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    both_at_once = both_at_once || running == 2;
  };
  std::thread other_caller(
      [&] { run_reporting(progress, [&](const Progress &) { meet(inner_thread); }); });
  run_reporting(progress, [&](const Progress &) { meet(outer_thread); });
  other_caller.join();
  EXPECT_TRUE(both_at_once);
  EXPECT_NE(outer_thread, inner_thread);

  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    alarm(20); // a job that never runs ends the child by SIGALRM
    int jobs_run = 0;
    for (int job = 0; job < 2; ++job)
      run_reporting(progress, [&](const Progress &relay) {
        relay.report(1.0, "done");
        ++jobs_run;
      });
    _exit(jobs_run == 2 ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
}

// A callback for any thread (the terminal's bar): the job runs on the caller's thread and its
// reports reach the callback as they come, ranges and cancelling as with any other.
TEST(Progress, ACallbackForAnyThreadIsCalledByTheJobItself) {
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<double> seen;
  bool on_caller = true;
  const Progress progress = Progress::on_any_thread([&](double fraction, const std::string &) {
    on_caller &= std::this_thread::get_id() == caller;
    seen.push_back(fraction);
    return seen.size() < 3;
  });
  EXPECT_TRUE(progress.any_thread());
  EXPECT_TRUE(progress.range(0.5, 1.0).any_thread());
  EXPECT_FALSE(Progress([](double, const std::string &) { return true; }).any_thread());
  EXPECT_THROW(run_reporting(progress,
                             [&](const Progress &relay) {
                               EXPECT_EQ(std::this_thread::get_id(), caller);
                               relay.report(0.5, "half");
                               relay.range(0.5, 1.0).report(0.5, "three quarters");
                               relay.report(1.0, "cancelled here");
                               ADD_FAILURE() << "the third report should have thrown";
                             }),
               Cancelled);
  EXPECT_TRUE(on_caller);
  EXPECT_EQ(seen, (std::vector<double>{0.5, 0.75, 1.0}));
}

} // namespace
} // namespace meromorph
