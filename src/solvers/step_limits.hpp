// Limits on how many steps and outputs one run may take, and the check that a step moves
// time at all: a step count past what a double or a long can hold, or a step below the
// floating-point resolution of t, would otherwise end a run silently without a step.
#pragma once

#include <string>

namespace finseg {

/// Most steps one run may take (time steps, pull steps, load steps): docs/scene.md.
constexpr double kMaxSteps = 1e9;

/// Most outputs one run may record (rows of each probe CSV, VTK frames): docs/scene.md.
constexpr double kMaxOutputs = 1e6;

/// Number of steps of length `h` over `span` (rounded up). Throws InputError(file, field,
/// "... steps; at most ...") when it exceeds `limit` or is not a finite number.
long checked_step_count(double span, double h, double limit, const std::string& file,
                        const std::string& field);

/// Same inside a solver, where the step came from the model (automatic step): throws
/// DivergenceError naming `solver` instead.
long solver_step_count(double span, double h, const std::string& solver);

/// Throws DivergenceError when a step of `h` from time (or drive displacement) `t` does not
/// change it: the run cannot go on, and ending it as finished would be a wrong result.
void require_step_advances(double t, double h, const std::string& solver);

}  // namespace finseg
