#include "core/blas_kernels.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>

namespace finseg {
namespace {

// Looked up, not linked: libblas.so.3 may be the reference BLAS or ATLAS (Debian's
// alternatives), which have none of these.
template <class F>
F blas_function(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_DEFAULT, name));
}

}  // namespace

std::string blas_kernels() {
  const auto name = blas_function<const char* (*)()>("openblas_get_corename");
  const char* core = name != nullptr ? name() : nullptr;
  return core != nullptr ? core : "";
}

std::string blas_kernels_for_cpu() {
#if defined(__x86_64__) && defined(__GNUC__)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl")) {
    return "SkylakeX";
  }
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return "Haswell";
  if (__builtin_cpu_supports("avx")) return "Sandybridge";
#endif
  return "";
}

std::string blas_kernels_to_switch_to(const std::string& current, const std::string& for_cpu,
                                      bool forced) {
  if (forced || current != "Prescott") return "";
  return for_cpu;
}

void use_cpu_blas_kernels() {
  static std::once_flag once;
  std::call_once(once, [] {
    const std::string core = blas_kernels_to_switch_to(blas_kernels(), blas_kernels_for_cpu(),
                                                       std::getenv("OPENBLAS_CORETYPE") != nullptr);
    // OpenBLAS's run-time selection (DYNAMIC_ARCH): forgetting the table and selecting again
    // reads OPENBLAS_CORETYPE as at load time. Serial OpenBLAS, no BLAS call in flight.
    const auto quit = blas_function<void (*)()>("gotoblas_dynamic_quit");
    const auto init = blas_function<void (*)()>("gotoblas_dynamic_init");
    if (core.empty() || quit == nullptr || init == nullptr) return;
    if (setenv("OPENBLAS_CORETYPE", core.c_str(), 1) != 0) return;
    quit();
    init();
  });
}

}  // namespace finseg
