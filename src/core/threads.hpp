// The process's thread count: the force-element loop's OpenMP threads, and whether the
// libraries' own OpenMP regions (CHOLMOD's) may run in parallel at all.
#pragma once

namespace finseg {

/// Threads the element loop may use (OpenMP's current limit; the default is one per core or
/// OMP_NUM_THREADS).
int thread_count();

/// Sets the threads of the element loop (n >= 1). With n = 1 no OpenMP region runs in
/// parallel, a library's included: CHOLMOD asks for 4 threads whatever the setting.
void set_thread_count(int n);

}  // namespace finseg
