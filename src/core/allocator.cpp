#include "core/allocator.hpp"

#include <malloc.h>

#include <atomic>
#include <mutex>

namespace finseg {

namespace {

std::atomic<bool> heap_only{false};  // keep_freed_memory has run

}  // namespace

void keep_freed_memory() {
  static std::once_flag once;
  std::call_once(once, [] {
    heap_only = true;
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    // glibc maps every block above M_MMAP_THRESHOLD (at most 32 MiB) on its own and unmaps it
    // at its free: the force Jacobian's blocks and UMFPACK's numeric factor (50-300 MB at
    // 6 300 segments) were faulted in afresh at every matrix. Without mmap the heap reuses them.
    mallopt(M_MMAP_MAX, 0);
  });
}

MappedAllocations::MappedAllocations() {
  if (!heap_only) return;
  mallopt(M_MMAP_THRESHOLD, 0);
  mallopt(M_MMAP_MAX, 1 << 16);
}

MappedAllocations::~MappedAllocations() {
  if (heap_only) mallopt(M_MMAP_MAX, 0);
}

}  // namespace finseg
