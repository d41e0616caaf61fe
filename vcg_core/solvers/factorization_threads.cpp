#include "solvers/factorization_threads.h"

#if defined(_OPENMP)
#include <omp.h>
#endif

namespace meromorph {

FactorizationThreads::FactorizationThreads() {
#if defined(_OPENMP)
  dynamic_before_ = omp_get_dynamic();
  threads_before_ = omp_get_max_threads();
  omp_set_dynamic(1);
  omp_set_num_threads(1);
#endif
}

FactorizationThreads::~FactorizationThreads() {
#if defined(_OPENMP)
  omp_set_num_threads(threads_before_);
  omp_set_dynamic(dynamic_before_);
#endif
}

} // namespace meromorph
