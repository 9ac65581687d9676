#include <chrono>

#include "core/error.hpp"
#include "solvers/integrators.hpp"

namespace finseg {

double output_interval(const SolverSettings& s) {
  return s.output_interval > 0 ? s.output_interval : s.t_end / 100.0;
}

SolverStats run_solver(const Model& model, State& state, const SolverSettings& settings,
                       const OutputCallback& on_output, const ProgressCallback& on_progress) {
  SolverStats stats;
  const auto start = std::chrono::steady_clock::now();
  const OutputCallback out = on_output ? on_output : [](const State&, const BodyForces&) {};
  const ProgressCallback prog = on_progress ? on_progress : [](double) {};
  try {
    switch (settings.kind) {
      case SolverKind::Explicit:
        run_explicit(model, state, settings, out, prog, stats);
        break;
      case SolverKind::Implicit:
        run_implicit(model, state, settings, out, prog, stats);
        break;
      case SolverKind::Static:
        run_static(model, state, settings, out, prog, stats);
        break;
    }
  } catch (const DivergenceError& e) {
    stats.status = "diverged";
    stats.message = e.what();
  }
  stats.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace finseg
