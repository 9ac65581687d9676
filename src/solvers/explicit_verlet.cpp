// Explicit velocity Verlet (kick-drift-kick) with rotations by the exponential map.
// Angular velocities are advanced through the world-frame angular momentum, so the
// gyroscopic term needs no special treatment.
#include <fmt/format.h>
#include <cmath>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "elements/chamber_gas.hpp"
#include "solvers/dofs.hpp"
#include "solvers/integrators.hpp"
#include "solvers/step_limits.hpp"
#include "solvers/stop_request.hpp"

namespace finseg {
namespace {

// Half kick: v += h/2 F/m, L_W += h/2 tau_W, then w_W = J_W^-1 L_W.
void kick(const Model& model, State& state, const BodyForces& f, double h) {
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    if (model.bodies[i].fixed) continue;
    const BodyDef& b = model.bodies[i];
    state.v_W[i] += h / b.mass * f.f_W[i];
    const Mat3& R = state.R_WB[i];
    const Vec3 L_B = b.J_B * (R.transpose() * state.w_W[i]) + h * (R.transpose() * f.tau_W[i]);
    state.w_W[i] = R * b.J_B.ldlt().solve(L_B);
  }
}

void drift(const Model& model, State& state, double h) {
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    if (model.bodies[i].fixed) continue;
    state.p_W[i] += h * state.v_W[i];
    // Angular momentum is conserved during the drift: rotate it with the body.
    const Mat3 dR = so3_exp<double>(h * state.w_W[i]);
    const Vec3 L_W = state.R_WB[i] * model.bodies[i].J_B * state.R_WB[i].transpose() * state.w_W[i];
    state.R_WB[i] = orthonormalize(dR * state.R_WB[i]);
    state.w_W[i] =
        state.R_WB[i] * model.bodies[i].J_B.ldlt().solve(state.R_WB[i].transpose() * L_W);
  }
}

double automatic_step(const Model& model, const State& state) {
  const double omega = highest_frequency(model, state);
  if (!(omega > 0)) return 1e-4;
  double zeta = 0;  // stiffness-proportional damping of the highest mode
  for (const ElementDef& e : model.elements) {
    for (int j = 0; j < 6; ++j) {
      if (e.K[j] > 0) zeta = std::max(zeta, 0.5 * omega * e.C[j] / e.K[j]);
    }
  }
  return 0.8 * 2.0 / omega * (std::sqrt(1 + zeta * zeta) - zeta);
}

// Saves what the next step needs (a run continued from a checkpoint of this state).
void remember(State& state, const BodyForces& f, double h, double next_output, double t0, long n) {
  state.solver = {h, next_output, t0, n, state.t, f.f_W, f.tau_W, {}, {}, 0};
}

// Between outputs the memory is stale; empty, it costs nothing in the per-step State copies.
void forget(State& state) {
  state.solver.f_W.clear();
  state.solver.tau_W.clear();
}

}  // namespace

void run_explicit(const Model& model, State& state, const SolverSettings& settings,
                  const OutputCallback& on_output, const ProgressCallback& on_progress,
                  SolverStats& stats) {
  // Continuing a run: its step, unless the settings fix another (the automatic step of the
  // resumed state differs from the start's wherever the stiffness changed, e.g. with a gas).
  const SolverMemory& mem = state.solver;
  const bool continues = mem.t == state.t && mem.next_output > state.t && mem.dt > 0 &&
                         (settings.dt <= 0 || settings.dt == mem.dt);
  const double h = continues         ? mem.dt
                   : settings.dt > 0 ? settings.dt
                                     : automatic_step(model, state);
  const double every = output_interval(settings);
  stats.smallest_step = stats.largest_step = h;
  set_quasi_static(state, false);
  set_drives_at_time(model, state, state.t);
  commit_history(model, state, true);  // the start is a state the structure is in
  BodyForces f;
  compute_forces(model, state, f);
  ++stats.force_evaluations;
  // Continuing a run: the first kick uses the forces the interrupted run would have used,
  // and the step count goes on from where it was (t = t0 + n h exactly as before).
  const bool resumed =
      continues && mem.f_W.size() == f.f_W.size() && mem.tau_W.size() == f.tau_W.size();
  const double t0 = resumed ? mem.t_start : state.t;
  const long n0 = resumed ? mem.steps : 0;
  double next_output = resumed ? mem.next_output : t0 + every;
  if (resumed) {
    f.f_W = mem.f_W;
    f.tau_W = mem.tau_W;
  }
  remember(state, f, h, next_output, t0, n0);
  on_output(state, f);
  forget(state);
  const long total = solver_step_count(settings.t_end - t0, h, "explicit solver");
  require_step_advances(std::max(std::abs(t0), std::abs(settings.t_end)), h, "explicit solver");
  for (long n = n0 + 1; n <= total; ++n) {
    const State last_good = state;
    kick(model, state, f, 0.5 * h);
    drift(model, state, h);
    state.t = t0 + n * h;
    set_drives_at_time(model, state, state.t);
    compute_forces(model, state, f);
    ++stats.force_evaluations;
    kick(model, state, f, 0.5 * h);
    try {
      check_finite(model, state, f, "explicit solver");
    } catch (const DivergenceError&) {
      state = last_good;
      throw;
    }
    commit_history(model, state);
    ++stats.steps;
    const bool at_output = state.t >= next_output - 1e-9 * h || n == total;
    if (at_output) {
      next_output += every;
      remember(state, f, h, next_output, t0, n);
      on_output(state, f);
      forget(state);
    }
    if (stop_requested()) {  // ends the run at this step, with what continuing it needs
      remember(state, f, h, next_output, t0, n);
      throw StopRequested{state.t};
    }
    on_progress({(state.t - t0) / (settings.t_end - t0), state.t, h, &stats});
  }
}

}  // namespace finseg
