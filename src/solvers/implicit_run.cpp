// The adaptive driver of the implicit solver, shared by its schemes: step size from the
// scheme's local error estimate, cuts after rejected steps and Newton failures, outputs on
// time, restarts of the scheme's history after contact events and crease snaps.
#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "elements/chamber_gas.hpp"
#include "solvers/dofs.hpp"
#include "solvers/integrators.hpp"
#include "solvers/step_limits.hpp"
#include "solvers/stop_request.hpp"
#include "solvers/time_stepper.hpp"

namespace finseg {
namespace {

// True when an accepted step changed what the forces are made of: a crease opened or
// closed, a contact point appeared or vanished. An anchor that started or stopped sliding is
// not one: it only moves its spring's cap, which a kept matrix's contraction test handles, and
// many pressed points flipping would renew the matrix at nearly every step (docs/solvers.md,
// "Modified Newton").
bool history_event(const State& before, const State& after) {
  for (size_t k = 0; k < before.history.size() && k < after.history.size(); ++k) {
    if (before.history[k].openings != after.history[k].openings ||
        before.history[k].opened != after.history[k].opened) {
      return true;
    }
  }
  const auto& a = before.contact.anchors;
  const auto& b = after.contact.anchors;
  if (a.size() != b.size()) return true;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].key != b[i].key) return true;
  }
  return false;
}

// The step from now to a mark (the next output or the end) at most `h` long: the distance is
// spread over equal steps, so that no sliver is left before the mark (a step of 1e-5 h there
// costs a whole Newton solve and, its coefficients far from the kept matrix's, a factorization
// for it and one after it: docs/solvers.md, "Step control").
double step_toward(double to_mark, double h) {
  if (to_mark <= h) return to_mark;
  // (1e-9: a distance a rounding above n steps is still n steps)
  return to_mark / std::ceil(to_mark / h - 1e-9);
}

std::unique_ptr<TimeStepper> make_stepper(const SolverSettings& s, double tol) {
  if (s.scheme == ImplicitScheme::GeneralizedAlpha) return make_generalized_alpha(s, tol);
  return make_backward_euler(s, tol);
}

}  // namespace

void run_implicit(const Model& model, State& state, const SolverSettings& settings,
                  const OutputCallback& on_output, const ProgressCallback& on_progress,
                  SolverStats& stats) {
  const double every = output_interval(settings);
  const double h_max = settings.dt_max > 0 ? settings.dt_max : every;
  // A run continued from a checkpoint keeps the interrupted run's output times and its next
  // step (a fresh first step would take the run along other steps).
  const bool resumed = state.solver.t == state.t && state.solver.next_output > state.t;
  double h = resumed && state.solver.dt > 0 ? std::min(h_max, state.solver.dt)
             : settings.dt > 0              ? settings.dt
                                            : std::min(h_max, every / 10);
  const double length_scale = std::max(model.sheet.length, 1e-3);
  const double tol = settings.atol + settings.rtol * length_scale;
  const std::unique_ptr<TimeStepper> stepper = make_stepper(settings, tol);
  const double root = 1.0 / stepper->error_order();
  set_quasi_static(state, false);
  set_drives_at_time(model, state, state.t);
  commit_history(model, state, true);  // the start is a state the structure is in
  BodyForces f;
  compute_forces(model, state, f);
  ++stats.force_evaluations;
  stepper->begin(model, state, f);
  const double t0 = state.t;
  double next_output = resumed ? state.solver.next_output : t0 + every;
  // What a checkpoint at this output needs to continue exactly as this run does.
  const auto memory = [&] {
    SolverMemory m;
    m.dt = h;
    m.next_output = next_output;
    m.t_start = t0;
    m.t = state.t;
    stepper->remember(m);
    return m;
  };
  state.solver = memory();
  on_output(state, f);
  stats.smallest_step = h;
  bool after_rejection = false;
  while (state.t < settings.t_end - 1e-12 * every) {
    const double h_try = step_toward(std::min(next_output, settings.t_end) - state.t,
                                     std::min(h, gas_step_limit(model, state)));
    require_step_advances(state.t, h_try, "implicit solver");
    const State start = state;
    const StepTry r = stepper->attempt(model, start, h_try, state, f, stats);
    if (!r.converged || r.error > 1.0) {
      state = start;
      ++stats.rejected_steps;
      if (!r.converged) ++stats.newton_failures;
      after_rejection = true;
      h = h_try * (r.converged ? std::max(0.2, 0.9 * std::pow(r.error, -root)) : 0.25);
      if (h < settings.dt_min) {
        throw DivergenceError(fmt::format(
            "implicit solver: step fell below dt_min = {:.3g} s at t = {:.6g} s ({}); most "
            "strained {}",
            settings.dt_min, state.t, r.converged ? "local error too large" : "Newton failed",
            most_strained_element(model, state)));
      }
      continue;
    }
    check_finite(model, state, f, "implicit solver");
    commit_history(model, state);
    stepper->accept(history_event(start, state));
    ++stats.steps;
    stats.smallest_step = std::min(stats.smallest_step, h_try);
    stats.largest_step = std::max(stats.largest_step, h_try);
    // The step the error of this one asks for, within 0.2 .. 2 of the step intended (this one
    // may have been shortened for a mark); no growth right after a rejection: the estimate
    // that failed is still close (Hairer).
    const double asked = 0.9 * h_try * std::pow(std::max(r.error, 1e-12), -root);
    h = std::min(h_max, std::clamp(asked, 0.2 * h, (after_rejection ? 1.0 : 2.0) * h));
    after_rejection = false;
    const bool at_output =
        state.t >= next_output - 1e-9 * every || state.t >= settings.t_end - 1e-12 * every;
    if (at_output) next_output += every;
    // A stop request ends the run here, not at the next output, which may be hours away on a
    // large model; the run continued from here keeps the output times.
    const bool stop = stop_requested();
    if (at_output || stop) {
      stepper->forget_newton_matrix();  // a run continued from here starts without one
      state.solver = memory();
    }
    if (at_output) on_output(state, f);
    if (stop) throw StopRequested{state.t};
    on_progress({(state.t - t0) / (settings.t_end - t0), state.t, h_try, &stats});
  }
}

}  // namespace finseg
