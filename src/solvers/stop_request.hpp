// Stop requests for running solvers (SIGINT/SIGTERM in `finseg run`). A request is only a
// flag, looked at where the State is consistent (history committed): after each output
// (run_solver) and after each accepted step of the dynamic solvers. The run ends there with
// status "interrupted" and `state` at that point, its solver memory set to continue from it.
#pragma once

namespace finseg {

/// Asks every running solver to stop at its next accepted step. Async-signal-safe.
void request_stop() noexcept;

/// True once request_stop() was called (until clear_stop_request()).
bool stop_requested() noexcept;

/// Forgets an earlier request (before starting a new run).
void clear_stop_request() noexcept;

/// Thrown where a run stops on request; run_solver catches it.
struct StopRequested {
  double t;  ///< where the run stopped (s; static: the load or drive parameter)
};

/// SolverStats::status of a run stopped by request_stop().
inline constexpr const char* kInterruptedStatus = "interrupted";

}  // namespace finseg
