// Progress reporting and cancellation, from the core up to every adapter.
//
// In:  a callback `bool(double fraction, const std::string &stage)` given by the adapter (CLI bar,
//      MeshLab's CallBackPos, Blender's progress_update); it returns false to cancel.
// Out: `Progress::report` calls it with a fraction in [0, 1]; when the callback asks to cancel,
//      `report` throws `Cancelled`. `Progress::range` hands a sub-stage its own 0..1 slice.
//      `run_reporting` runs a whole job on a worker thread of its own that reports into a relay,
//      while the calling thread hands the latest report to the callback at least every quarter
//      second: the callback (a GUI's) is only ever called on the caller's thread, steadily, and a
//      cancel stops the job at its next report.
#pragma once

#include <functional>
#include <string>

namespace meromorph {

class Progress {
public:
  using Callback = std::function<bool(double fraction, const std::string &stage)>;

  Progress() = default;
  explicit Progress(Callback callback) : callback_(std::move(callback)) {}

  // Reports `fraction` (0..1) of this range done; throws Cancelled if the callback says stop.
  void report(double fraction, const std::string &stage) const;

  // A progress object for a sub-stage that covers [begin, end] of this one.
  Progress range(double begin, double end) const;

  // A callback that may be called on the job's own thread, only when the job reports (a terminal
  // bar): run_reporting runs the job right there, with no thread of its own.
  static Progress on_any_thread(Callback callback);

  bool reports() const { return bool(callback_); }
  bool any_thread() const { return any_thread_; }

private:
  Progress(Callback callback, double begin, double end, bool any_thread)
      : callback_(std::move(callback)), begin_(begin), end_(end), any_thread_(any_thread) {}

  Callback callback_;
  double begin_ = 0.0;
  double end_ = 1.0;
  bool any_thread_ = false;
};

// `job(relay)` runs on a thread of its own (which ends with it); every 0.25 s the latest of its
// reports reaches `progress` from this thread (new or not: the bar stays alive), and the last one
// when it ends; its exception, if any, is thrown here. When the callback cancels, the job's next
// report throws Cancelled there and this call throws Cancelled once the job has unwound. Without a
// callback, or with one for any thread, the job simply runs here. (This thread is not woken by the
// job's reports: on two cores a third busy thread beside the job's two stalled a 4k-vertex map.)
void run_reporting(const Progress &progress, const std::function<void(const Progress &relay)> &job);

} // namespace meromorph
