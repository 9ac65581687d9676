// The C library's allocator tuned for Newton iterations (BENCHMARKS.md, "Folded strip" and
// "Implicit schemes": "Cost of a Newton iteration"; "The symmetric part in the cone's Newton
// iterations").
#pragma once

namespace finseg {

/// Makes glibc keep freed memory (up to 1 GiB) in its heap instead of handing it back to the
/// kernel at every free, and take every block from the heap (none mapped on its own): the
/// sparse matrices and factors a Newton iteration builds and drops otherwise cost page
/// faults and TLB flushes, up to 6 times the iteration's arithmetic on a 640-segment strip
/// and a quarter of a step on the 6 300-segment cone. Process-wide; once per process.
void keep_freed_memory();

/// While alive (after keep_freed_memory), every block is mapped on its own instead of taken
/// from the heap (a page at least: for a few blocks, not for many small ones). For data kept
/// to the end of a run (the recorded frames): in the heap even a small block splits a hole
/// that a Newton matrix is reused from, and the heap grows by a matrix, at 10^4 segments by
/// about 15 MB per output for 2.7 MB of frame (BENCHMARKS.md). On the thread that records,
/// between solves.
class MappedAllocations {
 public:
  MappedAllocations();
  ~MappedAllocations();
  MappedAllocations(const MappedAllocations&) = delete;
  MappedAllocations& operator=(const MappedAllocations&) = delete;
};

}  // namespace finseg
