// Which BLAS kernels finseg switches to (core/blas_kernels.hpp): only where OpenBLAS fell back to
// Prescott's, the CPU runs better ones and the user did not choose them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "core/blas_kernels.hpp"

namespace finseg {

TEST(BlasKernels, SwitchesOnlyFromPrescottsFallbackToWhatTheCpuRuns) {
  EXPECT_EQ(blas_kernels_to_switch_to("Prescott", "SkylakeX", false), "SkylakeX");
  EXPECT_EQ(blas_kernels_to_switch_to("Prescott", "Haswell", false), "Haswell");
  EXPECT_EQ(blas_kernels_to_switch_to("Prescott", "SkylakeX", true), "");  // the user's choice
  EXPECT_EQ(blas_kernels_to_switch_to("Prescott", "", false), "");         // an SSE3-only CPU
  EXPECT_EQ(blas_kernels_to_switch_to("Zen", "Haswell", false), "");       // a model it knows
  EXPECT_EQ(blas_kernels_to_switch_to("", "Haswell", false), "");          // not OpenBLAS
}

// The CPU's set from the kernel's own report of the instruction set (/proc/cpuinfo's flags).
TEST(BlasKernels, TheCpusSetFollowsItsFlagsInProcCpuinfo) {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line) && line.rfind("flags", 0) != 0) {
  }
  if (line.empty()) GTEST_SKIP() << "no /proc/cpuinfo flags";
  std::set<std::string> flags;
  std::istringstream words(line.substr(line.find(':') + 1));
  for (std::string w; words >> w;) flags.insert(w);
  const auto has = [&](const char* f) { return flags.count(f) > 0; };
  std::string expected;
  if (has("avx512f") && has("avx512bw") && has("avx512dq") && has("avx512vl")) {
    expected = "SkylakeX";
  } else if (has("avx2") && has("fma")) {
    expected = "Haswell";
  } else if (has("avx")) {
    expected = "Sandybridge";
  }
  EXPECT_EQ(blas_kernels_for_cpu(), expected);
}

// The switch as a factorization makes it: OpenBLAS then reports the CPU's set where it had
// fallen back to Prescott's (and the user did not choose), else what it had.
TEST(BlasKernels, AFactorizationLeavesOpenBlasOnTheCpusKernels) {
  const std::string before = blas_kernels();
  const bool forced = std::getenv("OPENBLAS_CORETYPE") != nullptr;
  use_cpu_blas_kernels();
  const std::string expected = blas_kernels_to_switch_to(before, blas_kernels_for_cpu(), forced);
  EXPECT_EQ(blas_kernels(), expected.empty() ? before : expected);
}

}  // namespace finseg
