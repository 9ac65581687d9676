#include "core/threads.hpp"

#include <omp.h>

namespace finseg {

int thread_count() {
  return omp_get_max_threads();
}

void set_thread_count(int n) {
  // SuiteSparse 5's supernodal CHOLMOD opens its regions with num_threads(4), which
  // OMP_NUM_THREADS does not limit: on the 2-core VM those threads took 37 % of the CPU of
  // a one-thread cone pull (docs/solvers.md, "Threads"). No active level at all keeps every
  // region on the calling thread.
  static const int levels = omp_get_max_active_levels();
  omp_set_num_threads(n);
  omp_set_max_active_levels(n == 1 ? 0 : levels);
}

}  // namespace finseg
