#include "solvers/factorization_threads.h"

#if defined(_OPENMP)
#include <omp.h>
#endif

namespace meromorph {

FactorizationThreads::FactorizationThreads() {
#if defined(_OPENMP)
  levels_before_ = omp_get_max_active_levels();
  omp_set_max_active_levels(0);
#endif
}

FactorizationThreads::~FactorizationThreads() {
#if defined(_OPENMP)
  omp_set_max_active_levels(levels_before_);
#endif
}

} // namespace meromorph
