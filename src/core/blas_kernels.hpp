// Which kernels the BLAS under CHOLMOD and UMFPACK runs. OpenBLAS built for many CPUs
// (Debian's) picks its kernels by the CPU's model and, on a model newer than it knows, falls
// back to Prescott's (SSE3): Debian 12's 0.3.21 does so on Intel family 6 model 207 (a Xeon
// VM with AVX-512), where the 10^4-segment cone's deploy then takes 30 % more time
// (BENCHMARKS.md, "BLAS kernels on a CPU OpenBLAS does not know"). finseg then selects the
// kernels the CPU's instruction set runs, as OPENBLAS_CORETYPE would have at load time.
#pragma once

#include <string>

namespace finseg {

/// The BLAS's kernel set as OpenBLAS names it ("Haswell", "SkylakeX", ...), or "" when the BLAS
/// linked is not OpenBLAS.
std::string blas_kernels();

/// The best OpenBLAS kernel set this CPU's instruction set runs: "SkylakeX" (AVX-512 F, BW, DQ,
/// VL), "Haswell" (AVX2 and FMA), "Sandybridge" (AVX), else "".
std::string blas_kernels_for_cpu();

/// The kernel set to switch to: `for_cpu` where OpenBLAS fell back to Prescott's (`current`),
/// the CPU runs better ones (`for_cpu` not empty) and OPENBLAS_CORETYPE was not given
/// (`forced`); else "".
std::string blas_kernels_to_switch_to(const std::string& current, const std::string& for_cpu,
                                      bool forced);

/// Once per process, before the first factorization: where OpenBLAS fell back to Prescott's
/// kernels on a CPU that runs better ones, selects those (and sets OPENBLAS_CORETYPE for child
/// processes). Results are then those of a process started with OPENBLAS_CORETYPE set, to the
/// bit. Nothing happens with another BLAS, or an OpenBLAS without run-time kernel selection.
void use_cpu_blas_kernels();

}  // namespace finseg
