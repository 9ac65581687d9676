// Implicit backward Euler on (pose, momentum) with Newton on the exact sparse Jacobian and
// an adaptive step from the local error estimate h/2 |v_{n+1} - v_n| (the role of Adams'
// GSTIFF). Backward Euler dissipates: it never adds energy to an undriven system.
#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "solvers/dofs.hpp"
#include "solvers/integrators.hpp"
#include "solvers/linear_solve.hpp"
#include "solvers/step_limits.hpp"

namespace finseg {
namespace {

struct StepResult {
  bool converged = false;
  int iterations = 0;
};

// Solves M(q1) v1 - p0 = h g(q0 + h v1, v1) for v1, leaving the state at (q1, v1).
StepResult backward_euler_step(const Model& model, State& state, const State& start, double h,
                               int max_iterations, double atol, BodyForces& f, SolverStats& stats) {
  const Eigen::VectorXd p0 = momentum(model, start);
  Eigen::VectorXd v = velocity_vector(model, start);
  StepResult r;
  ForceJacobian jac;
  for (r.iterations = 1; r.iterations <= max_iterations; ++r.iterations) {
    state = start;
    state.t = start.t + h;
    set_drives_at_time(model, state, state.t);
    apply_pose_increment(model, state, h * v);
    set_velocity(model, state, v);
    compute_forces(model, state, f, &jac);
    ++stats.force_evaluations;
    ++stats.jacobian_evaluations;
    ++stats.newton_iterations;
    const Eigen::SparseMatrix<double> M = mass_matrix(model, state);
    const Eigen::VectorXd res = momentum(model, state) - p0 - h * generalized_forces(model, f);
    const Eigen::SparseMatrix<double> A = M - h * jac.dv - (h * h) * jac.dq;
    Eigen::VectorXd dv;
    if (!res.allFinite() || !sparse_solve(A, -res, dv)) return r;
    v += dv;
    if (h * dv.lpNorm<Eigen::Infinity>() < 1e-3 * atol) {
      state = start;
      state.t = start.t + h;
      set_drives_at_time(model, state, state.t);
      apply_pose_increment(model, state, h * v);
      set_velocity(model, state, v);
      compute_forces(model, state, f);
      ++stats.force_evaluations;
      r.converged = true;
      return r;
    }
  }
  return r;
}

}  // namespace

void run_implicit(const Model& model, State& state, const SolverSettings& settings,
                  const OutputCallback& on_output, const ProgressCallback& on_progress,
                  SolverStats& stats) {
  const double every = output_interval(settings);
  const double h_max = settings.dt_max > 0 ? settings.dt_max : every;
  double h = settings.dt > 0 ? settings.dt : std::min(h_max, every / 10);
  const double length_scale = std::max(model.sheet.length, 1e-3);
  const double tol = settings.atol + settings.rtol * length_scale;
  set_drives_at_time(model, state, state.t);
  commit_history(model, state);  // the start is a state the structure is in
  BodyForces f;
  compute_forces(model, state, f);
  ++stats.force_evaluations;
  // A run continued from a checkpoint keeps the interrupted run's output times.
  const bool resumed = state.solver.t == state.t && state.solver.next_output > state.t;
  const double t0 = state.t;
  double next_output = resumed ? state.solver.next_output : t0 + every;
  state.solver = {h, next_output, t0, 0, state.t, {}, {}};
  on_output(state, f);
  stats.smallest_step = h;
  while (state.t < settings.t_end - 1e-12 * every) {
    const double h_try = std::min({h, next_output - state.t, settings.t_end - state.t});
    require_step_advances(state.t, h_try, "implicit solver");
    const State start = state;
    const StepResult r =
        backward_euler_step(model, state, start, h_try, settings.max_iterations, tol, f, stats);
    double err = 2.0;
    if (r.converged) {
      const Eigen::VectorXd dv = velocity_vector(model, state) - velocity_vector(model, start);
      err = 0.5 * h_try * dv.lpNorm<Eigen::Infinity>() / tol;
    }
    if (!r.converged || err > 1.0) {
      state = start;
      ++stats.rejected_steps;
      h = h_try * (r.converged ? std::max(0.2, 0.9 / std::sqrt(err)) : 0.25);
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
    ++stats.steps;
    stats.smallest_step = std::min(stats.smallest_step, h_try);
    stats.largest_step = std::max(stats.largest_step, h_try);
    const double grown = h_try * std::clamp(0.9 / std::sqrt(std::max(err, 1e-12)), 0.2, 2.0);
    // A step shortened only to land on an output time says nothing about the next one.
    h = std::min(h_max, h_try < h ? std::max(h, grown) : grown);
    if (state.t >= next_output - 1e-9 * every || state.t >= settings.t_end - 1e-12 * every) {
      next_output += every;
      state.solver = {h, next_output, t0, 0, state.t, {}, {}};
      on_output(state, f);
      on_progress((state.t - t0) / (settings.t_end - t0));
    }
  }
}

}  // namespace finseg
