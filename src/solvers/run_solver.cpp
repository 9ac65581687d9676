#include <fmt/format.h>

#include <atomic>
#include <chrono>

#include "core/allocator.hpp"
#include "core/error.hpp"
#include "solvers/integrators.hpp"
#include "solvers/stop_request.hpp"

namespace finseg {
namespace {

// Signal handlers may only touch lock-free atomics.
std::atomic<bool> g_stop{false};
static_assert(std::atomic<bool>::is_always_lock_free);

}  // namespace

void request_stop() noexcept {
  g_stop.store(true);
}

bool stop_requested() noexcept {
  return g_stop.load();
}

void clear_stop_request() noexcept {
  g_stop.store(false);
}

double output_interval(const SolverSettings& s) {
  return s.output_interval > 0 ? s.output_interval : s.t_end / 100.0;
}

SolverStats run_solver(const Model& model, State& state, const SolverSettings& settings,
                       const OutputCallback& on_output, const ProgressCallback& on_progress) {
  keep_freed_memory();  // from the library too: benchmarks, tests and the Python module
  SolverStats stats;
  const LinearSolveCounters linear_before = linear_solve_counters();
  const auto start = std::chrono::steady_clock::now();
  // Every solver, present or future, stops at its outputs: the wrapper checks the flag after
  // the caller has recorded the output, so nothing recorded is lost.
  const OutputCallback out = [&on_output](const State& s, const BodyForces& f) {
    if (on_output) on_output(s, f);
    if (stop_requested()) throw StopRequested{s.t};
  };
  const ProgressCallback prog = on_progress ? on_progress : [](const SolverProgress&) {};
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
  } catch (const StopRequested& stop) {
    stats.status = kInterruptedStatus;
    stats.message = fmt::format("stopped on request at t = {:.6g}", stop.t);
  }
  stats.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.linear = linear_solve_counters() - linear_before;
  return stats;
}

}  // namespace finseg
