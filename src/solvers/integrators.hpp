// The three solver implementations behind run_solver (internal to solvers/).
#pragma once

#include "solvers/solver.hpp"

namespace finseg {

void run_explicit(const Model& model, State& state, const SolverSettings& settings,
                  const OutputCallback& on_output, const ProgressCallback& on_progress,
                  SolverStats& stats);
void run_implicit(const Model& model, State& state, const SolverSettings& settings,
                  const OutputCallback& on_output, const ProgressCallback& on_progress,
                  SolverStats& stats);
void run_static(const Model& model, State& state, const SolverSettings& settings,
                const OutputCallback& on_output, const ProgressCallback& on_progress,
                SolverStats& stats);

/// Highest natural angular frequency (rad/s) of the linearised system at `state`.
double highest_frequency(const Model& model, const State& state);

/// Output interval of a dynamic run (settings.output_interval or t_end / 100).
double output_interval(const SolverSettings& settings);

}  // namespace finseg
