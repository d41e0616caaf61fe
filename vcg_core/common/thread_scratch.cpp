#include "common/thread_scratch.h"

#if defined(_OPENMP)
#include <omp.h>
#endif

namespace meromorph {

std::vector<std::function<void()>> &thread_scratch_releases() {
  thread_local std::vector<std::function<void()>> releases;
  return releases;
}

void release_team_scratch() {
#if defined(_OPENMP)
#pragma omp parallel
#endif
  for (const std::function<void()> &release : thread_scratch_releases())
    release();
}

} // namespace meromorph
