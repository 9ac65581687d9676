// The C library's allocator tuned for Newton iterations (BENCHMARKS.md, "Folded strip" and
// "Implicit schemes": "Cost of a Newton iteration").
#pragma once

namespace finseg {

/// Makes glibc keep freed memory (up to 256 MiB, blocks below 32 MiB from the heap) instead
/// of handing it back to the kernel at every free: the sparse matrices a Newton iteration
/// builds and drops otherwise cost page faults and TLB flushes, up to 6 times the iteration's
/// arithmetic on a 640-segment strip. Process-wide; once per process, on the first call.
void keep_freed_memory();

}  // namespace finseg
