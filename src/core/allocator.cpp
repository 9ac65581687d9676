#include "core/allocator.hpp"

#include <malloc.h>

#include <mutex>

namespace finseg {

void keep_freed_memory() {
  static std::once_flag once;
  std::call_once(once, [] {
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
  });
}

}  // namespace finseg
