#include "common/progress.h"

#include <algorithm>

#include "common/errors.h"

namespace meromorph {

void Progress::report(double fraction, const std::string &stage) const {
  if (!callback_) return;
  const double clamped = std::clamp(fraction, 0.0, 1.0);
  if (!callback_(begin_ + (end_ - begin_) * clamped, stage)) throw Cancelled();
}

Progress Progress::range(double begin, double end) const {
  const double width = end_ - begin_;
  return Progress(callback_, begin_ + width * begin, begin_ + width * end);
}

} // namespace meromorph
