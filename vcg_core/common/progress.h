// Progress reporting and cancellation, from the core up to every adapter.
//
// In:  a callback `bool(double fraction, const std::string &stage)` given by the adapter (CLI bar,
//      MeshLab's CallBackPos, Blender's progress_update); it returns false to cancel.
// Out: `Progress::report` calls it with a fraction in [0, 1]; when the callback asks to cancel,
//      `report` throws `Cancelled`. `Progress::range` hands a sub-stage its own 0..1 slice.
//      `run_reporting` runs a whole job on a worker thread that reports into a relay, while the
//      calling thread hands the latest report to the callback at least every quarter second:
//      the callback (a GUI's) is only ever called on the caller's thread, steadily, and a cancel
//      stops the job at its next report.
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

  bool reports() const { return bool(callback_); }

private:
  Progress(Callback callback, double begin, double end)
      : callback_(std::move(callback)), begin_(begin), end_(end) {}

  Callback callback_;
  double begin_ = 0.0;
  double end_ = 1.0;
};

// `job(relay)` runs on another thread; its reports reach `progress` from this thread, the latest
// one again every 0.25 s while nothing new comes; its exception, if any, is thrown here. When
// the callback cancels, the job's next report throws Cancelled there and this call throws
// Cancelled once the job has unwound. Without a callback the job simply runs here.
void run_reporting(const Progress &progress, const std::function<void(const Progress &relay)> &job);

} // namespace meromorph
