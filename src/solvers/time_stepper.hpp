// One step of an implicit scheme, behind the adaptive driver of run_implicit
// (solvers/implicit_run.cpp): backward Euler and generalized-alpha (docs/solvers.md).
#pragma once

#include <memory>

#include "solvers/solver.hpp"

namespace finseg {

/// Outcome of one attempted step.
struct StepTry {
  bool converged = false;  ///< Newton converged
  double error = 2;        ///< local error estimate relative to the tolerance (<= 1: accept)
};

/// A one-step implicit scheme with its own history (accelerations for generalized-alpha).
class TimeStepper {
 public:
  virtual ~TimeStepper() = default;
  /// Starts the history from `state` and its forces `f` (t = 0 and after a restart), or from
  /// state.solver where it holds this scheme's memory at state.t (a resumed run).
  virtual void begin(const Model& model, const State& state, const BodyForces& f) = 0;
  /// Writes the history into `memory`, so that a run resumed from it continues exactly.
  virtual void remember(SolverMemory& memory) const = 0;
  /// Advances `start` by h into `state` (forces in `f`); touches no history.
  virtual StepTry attempt(const Model& model, const State& start, double h, State& state,
                          BodyForces& f, SolverStats& stats) = 0;
  /// Drops what Newton kept between steps (its iteration matrix): at each output, so that a
  /// run resumed from that output's checkpoint continues exactly as the uninterrupted one.
  virtual void forget_newton_matrix() = 0;
  /// Takes the last attempt's result as the new history; `restart` after an event (contact
  /// made or lost, a crease snapped) that makes the old accelerations meaningless.
  virtual void accept(bool restart) = 0;
  /// p where the local error estimate scales as h^p (step control uses err^(-1/p)).
  virtual double error_order() const = 0;
};

/// Backward Euler in momentum form; `tol` is the local error tolerance, m and rad.
std::unique_ptr<TimeStepper> make_backward_euler(const SolverSettings& settings, double tol);
/// Generalized-alpha (Chung-Hulbert) on the Lie group of poses.
std::unique_ptr<TimeStepper> make_generalized_alpha(const SolverSettings& settings, double tol);

}  // namespace finseg
