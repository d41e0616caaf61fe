#include "common/progress.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <future>
#include <memory>
#include <mutex>
#include <thread>

#include <pthread.h>

#include "common/errors.h"
#include "common/parallel_for.h"
#include "common/thread_scratch.h"

namespace meromorph {
namespace {

// The thread relayed jobs run on, kept for the next job. A thread of its own for every job made
// OpenMP start a new team for every job, while the last job's team still spun on the two cores:
// a 2.3k-vertex genus-0 map through the C library with a progress callback (as the Blender add-on
// calls it), calls 3 to 12 of three runs, took 27.4 ms (median; 11.1 to 39.8) and now 11.8 (11.2
// to 16.6). The kept thread runs one job at a time; a job that comes while it is busy (another
// caller's) gets a thread of its own.
class KeptJobThread {
public:
  using Work = std::function<std::exception_ptr()>;               // the job; what it threw, or null
  using Delivery = std::function<void(std::exception_ptr error)>; // called once the thread is free

  // Runs `work` on the kept thread, or on a thread of its own if that one is busy, and then
  // `deliver` with what it threw.
  void run(Work work, Delivery deliver) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!busy_) {
        busy_ = true;
        work_ = std::move(work);
        deliver_ = std::move(deliver);
        if (!started_) {
          std::thread(&KeptJobThread::serve, this).detach();
          started_ = true;
        }
        wake_.notify_one();
        return;
      }
    }
    std::thread([work = std::move(work), deliver = std::move(deliver)] {
      deliver(work());
    }).detach();
  }

  // The process's; never destroyed: its thread waits for the next job until the process ends (a
  // library holding it is not unloaded by its hosts: MeshLab, Python's ctypes). A child of fork()
  // has none of its parent's threads: it gets an object of its own, whose thread starts at its
  // first job (the parent's object is left as the fork found it, never used there).
  static KeptJobThread &instance() {
    static std::once_flag once;
    std::call_once(once, [] {
      current() = new KeptJobThread;
      pthread_atfork(nullptr, nullptr, [] { current() = new KeptJobThread; });
    });
    return *current();
  }

private:
  static KeptJobThread *&current() {
    static KeptJobThread *kept = nullptr;
    return kept;
  }

  void serve() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      wake_.wait(lock, [&] { return bool(work_); });
      const Work work = std::move(work_);
      const Delivery deliver = std::move(deliver_);
      work_ = nullptr;
      deliver_ = nullptr;
      lock.unlock();
      const std::exception_ptr error = work();
      release_team_scratch(); // this thread outlives the job: common/thread_scratch.h
      lock.lock();
      busy_ = false; // free before the caller hears the job is done
      lock.unlock();
      deliver(error);
      lock.lock();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  Work work_;
  Delivery deliver_;
  bool busy_ = false, started_ = false;
};

} // namespace

void Progress::report(double fraction, const std::string &stage) const {
  if (!callback_) return;
  const double clamped = std::clamp(fraction, 0.0, 1.0);
  if (!callback_(begin_ + (end_ - begin_) * clamped, stage)) throw Cancelled();
}

Progress Progress::range(double begin, double end) const {
  const double width = end_ - begin_;
  return Progress(callback_, begin_ + width * begin, begin_ + width * end, any_thread_);
}

Progress Progress::on_any_thread(Callback callback) {
  return Progress(std::move(callback), 0.0, 1.0, true);
}

void run_reporting(const Progress &progress,
                   const std::function<void(const Progress &relay)> &job) {
  if (!progress.reports() || progress.any_thread()) {
    job(progress);
    return;
  }
  struct Relay {
    std::mutex mutex;
    std::condition_variable changed;
    double fraction = 0;
    std::string stage;
    bool fresh = false, cancelled = false, finished = false;
  } relay;
  const Progress relayed([&relay](double fraction, const std::string &stage) {
    const std::lock_guard<std::mutex> lock(relay.mutex);
    relay.fraction = fraction;
    relay.stage = stage;
    relay.fresh = true;
    return !relay.cancelled;
  });
  auto ended = std::make_shared<std::promise<void>>();
  std::future<void> done = ended->get_future();
  auto work = [&]() -> std::exception_ptr {
    try {
      // This thread's OpenMP team started at once, giving way to its threads (their first
      // parallel loop waited up to 12 ms for them otherwise: common/parallel_for.h).
      while_threads_start([] {});
      job(relayed);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(relay.mutex);
      relay.finished = true;
      relay.changed.notify_one();
      return std::current_exception();
    }
    const std::lock_guard<std::mutex> lock(relay.mutex);
    relay.finished = true;
    relay.changed.notify_one();
    return nullptr;
  };
  KeptJobThread::instance().run(work, [ended](std::exception_ptr error) {
    if (error)
      ended->set_exception(error);
    else
      ended->set_value();
  });
  try {
    std::unique_lock<std::mutex> lock(relay.mutex);
    while (true) {
      relay.changed.wait_for(lock, std::chrono::milliseconds(250), [&] { return relay.finished; });
      if (relay.finished && !relay.fresh) break;         // a last report is handed on first
      if (relay.stage.empty() && !relay.fresh) continue; // nothing reported yet
      const double fraction = relay.fraction;
      const std::string stage = relay.stage;
      relay.fresh = false;
      lock.unlock();
      progress.report(fraction, stage); // throws Cancelled when the callback says stop
      lock.lock();
    }
  } catch (...) {
    {
      const std::lock_guard<std::mutex> lock(relay.mutex);
      relay.cancelled = true;
    }
    done.wait(); // the job reads the caller's data: it must end before anything unwinds
    throw;
  }
  done.get(); // the job's own exception, if any
}

} // namespace meromorph
