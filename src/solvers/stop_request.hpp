// Stop requests for running solvers (SIGINT/SIGTERM in `finseg run`). A request is only a
// flag: run_solver checks it after each output, where the State is consistent (history
// committed), ends the run with status "interrupted" and leaves `state` at that output.
#pragma once

namespace finseg {

/// Asks every running solver to stop at its next output. Async-signal-safe.
void request_stop() noexcept;

/// True once request_stop() was called (until clear_stop_request()).
bool stop_requested() noexcept;

/// Forgets an earlier request (before starting a new run).
void clear_stop_request() noexcept;

/// SolverStats::status of a run stopped by request_stop().
inline constexpr const char* kInterruptedStatus = "interrupted";

}  // namespace finseg
