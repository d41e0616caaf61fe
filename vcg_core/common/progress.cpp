#include "common/progress.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <future>
#include <memory>
#include <mutex>
#include <thread>

#include "common/errors.h"
#include "common/parallel_for.h"

namespace meromorph {

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
  // The job on a thread of its own, which ends with it (and its OpenMP team with it).
  std::future<void> done = std::async(std::launch::async, [&] {
    try {
      // This thread's OpenMP team started at once, giving way to its threads (their first
      // parallel loop waited up to 12 ms for them otherwise: common/parallel_for.h).
      while_threads_start([] {});
      job(relayed);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(relay.mutex);
      relay.finished = true;
      relay.changed.notify_one();
      throw;
    }
    const std::lock_guard<std::mutex> lock(relay.mutex);
    relay.finished = true;
    relay.changed.notify_one();
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
