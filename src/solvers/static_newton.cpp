// Static equilibrium (the role of Adams' EQUILIBRIUM): Newton on the exact stiffness with a
// backtracking line search, load stepping with step halving, and quasi-static drive paths
// run as a sequence of equilibria.
#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "collision/contact_forces.hpp"
#include "core/error.hpp"
#include "elements/chamber_gas.hpp"
#include "elements/joint_rotation_history.hpp"
#include "elements/pressure.hpp"
#include "solvers/dofs.hpp"
#include "solvers/integrators.hpp"
#include "solvers/linear_solve.hpp"
#include "solvers/step_limits.hpp"
#include "solvers/stiff_projection.hpp"
#include "solvers/translation_solve.hpp"
#include "solvers/volume_stiffness.hpp"

namespace finseg {
namespace {

// Force scale for the convergence test: external loads, weight and gauge forces.
double force_scale(const Model& model) {
  double f = 0;
  const double L = std::max(model.sheet.length, 1e-3);
  for (const LoadDef& l : model.loads) f = std::max(f, l.force.norm() + l.moment.norm() / L);
  double weight = 0;
  for (const BodyDef& b : model.bodies) weight += b.mass;
  f = std::max(f, weight * model.gravity_W.norm());
  f = std::max(f, largest_pressure_force(model));
  f = std::max(f, largest_chamber_force(model));
  f = std::max(f, model.actuation_force);
  for (const DriveDef& d : model.drives) {
    f = std::max(f, d.stiffness * std::max(d.step, 1e-3 * L));
  }
  return std::max(f, 1e-9);
}

double residual_norm(const Model& model, const BodyForces& f) {
  const double L = std::max(model.sheet.length, 1e-3);
  double r = 0;
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    if (model.bodies[i].fixed) continue;
    r = std::max({r, f.f_W[i].lpNorm<Eigen::Infinity>(), f.tau_W[i].lpNorm<Eigen::Infinity>() / L});
  }
  return r;
}

// Largest translation (relative to the length scale L) or rotation (rad) in a correction.
double newton_step_size(const Eigen::VectorXd& dq, double L) {
  double step = 0;
  for (int i = 0; i + 5 < dq.size(); i += 6) {
    step = std::max({step, dq.segment<3>(i).lpNorm<Eigen::Infinity>() / L,
                     dq.segment<3>(i + 3).lpNorm<Eigen::Infinity>()});
  }
  return step;
}

// Work of the dead load moments over the pose increment dq (exact: each body turns about
// the fixed world axis of its rotation increment).
double dead_moment_work(const Model& model, const State& state, const Eigen::VectorXd& dq) {
  double w = 0;
  for (const LoadDef& l : model.loads) {
    const int d = model.dof_of_body[l.body];
    if (l.follower || d < 0) continue;
    w += state.load_scale * l.moment.dot(dq.segment<3>(d + 3));
  }
  return w;
}

// The matrix Newton solves with, from the exact stiffness K. A conservative model's K is
// symmetric but for the left-trivialisation term (1/2)[tau]x of each body's out-of-balance
// torque (elements/assemble.hpp): its symmetric part is the Hessian of the energy in the
// exponential chart at the current poses, so Newton on it converges quadratically, and it goes
// to the sparse Cholesky instead of LU (docs/solvers.md, "Linear solves").
// Gas in chambers (not conservative here) adds its stiffness against volume changes
// (solvers/volume_stiffness.hpp).
bool solve_newton_system(const Model& model, const State& state,
                         const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& g,
                         Eigen::VectorXd& dq) {
  if (!conservative_stiffness(model)) {
    return solve_with_volume_stiffness(K, 1.0, volume_stiffness(model, state), g, dq);
  }
  return sparse_solve(SymmetricMatrix::symmetric_part_of(K), g, dq);
}

// Levenberg-Marquardt shift of an indefinite Newton matrix: K + mu diag(|K_ii|) is factored
// with increasing mu until the L L^T succeeds (docs/solvers.md, "Static solver").
constexpr double kFirstShift = 1e-3, kShiftGrowth = 4, kShiftDecay = 0.25, kSmallestShift = 1e-6;
constexpr int kMaxShifts = 12;

// Newton step of a conservative model: K (symmetric part) if positive definite, else the
// shifted matrix. `mu` is the shift of the last step (0: none) and on return this one's.
// False if no shift up to the largest made K positive definite or K is not finite.
bool shifted_newton_step(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& g,
                         Eigen::VectorXd& dq, double& mu) {
  const SymmetricMatrix S = SymmetricMatrix::symmetric_part_of(K);
  mu *= kShiftDecay;
  if (mu < kSmallestShift) {
    mu = 0;
    const CholeskyStatus status = cholesky_solve(S, g, dq);
    if (status != CholeskyStatus::NotPositiveDefinite) return status == CholeskyStatus::Solved;
    mu = kFirstShift;
  }
  const Eigen::VectorXd d = S.shift_scale();
  for (int k = 0; k < kMaxShifts; ++k, mu *= kShiftGrowth) {
    const CholeskyStatus status = cholesky_solve(S.plus_diagonal(mu * d), g, dq);
    if (status != CholeskyStatus::NotPositiveDefinite) return status == CholeskyStatus::Solved;
  }
  return false;
}

// A Newton solve that has not reduced the residual by this factor after `stall_iteration`
// iterations is outside its region of quadratic convergence (the increment crosses a contact
// or friction transition, or is simply too long): along a drive path it is cheaper, and keeps
// to the path the slow pull follows, to give it up and cut the increment.
constexpr double kStallDrop = 0.03;

// A Newton step may carry a plate through another before their contact switches on; the
// equilibrium found then holds them interpenetrating. Two plates overlapping by more than half
// the thinner one's thickness are taken as such and the increment is cut.
bool tunnelled(const Model& model, const State& state) {
  if (!model.contact.enabled) return false;
  for (const ContactPairForce& p : contact_summary(model, state).pairs) {
    const double thinner = std::min(model.bodies[p.a].thickness, model.bodies[p.b].thickness);
    if (p.max_penetration > 0.5 * thinner) return true;
  }
  return false;
}

// A Newton trial turning a body by more than this (rad) is checked for tunnelling.
constexpr double kLongTurn = 0.25;

// The projected trial's largest turn (rad): the joints' misfit grows as its square, and the
// projection closes it from a short step (the 700-segment lab cone's fold, docs/folding.md:
// 0.05 took 151 Newton iterations, 0.02 326, 0.2 183, 1 rad 701).
constexpr double kProjectedTurn = 0.05;

// Newton from the current state at the current load scale and drive positions; with
// stall_iteration > 0 it gives up when stalled (kStallDrop).
bool solve_equilibrium(const Model& model, State& state, const SolverSettings& settings,
                       double fscale, BodyForces& f, SolverStats& stats, int stall_iteration = 0) {
  ForceJacobian jac;
  jac.with_velocity = false;  // statics needs d(force)/d(pose) only
  const double L = std::max(model.sheet.length, 1e-3);
  double r_start = 0;
  double mu = 0;  // Levenberg-Marquardt shift of the last step
  const bool conservative = conservative_stiffness(model);
  for (int it = 0; it < newton_iterations(settings); ++it) {
    compute_forces(model, state, f, &jac);
    ++stats.force_evaluations;
    ++stats.jacobian_evaluations;
    ++stats.newton_iterations;
    const double r0 = residual_norm(model, f);
    if (!std::isfinite(r0)) return false;
    if (r0 <= settings.tolerance * fscale) return true;
    if (it == 0) r_start = r0;
    if (stall_iteration > 0 && it >= stall_iteration && r0 > kStallDrop * r_start) return false;
    const Eigen::VectorXd g = generalized_forces(model, f);
    Eigen::VectorXd dq;
    // The first iteration's matrix is that of the start (an equilibrium, or the initial
    // state): not positive definite there means a mechanism (singular), reported below, or a
    // structure past a limit point, which L D L^T takes; shifts are for the iterates between.
    const bool solved = conservative && it > 0 ? shifted_newton_step(-jac.dq, g, dq, mu)
                                               : solve_newton_system(model, state, -jac.dq, g, dq);
    if (!solved) {
      // Slipping contact points carry a constant force: a part held only by friction
      // beyond its friction cone has no stiffness left along the slip.
      const bool friction = model.contact.enabled && model.contact.friction != FrictionModel::None;
      throw DivergenceError(fmt::format(
          "static solver: stiffness matrix is singular at t = {:.6g}: the structure is not "
          "restrained (add a fixture), has a mechanism{}; most strained {}",
          state.t,
          friction ? " or slips (tangential load beyond mu_static times the normal force)" : "",
          most_strained_element(model, state)));
    }
    // A Newton correction this small leaves an error of its square: converged, even where
    // round-off in the stiff in-plane springs keeps the residual above the force tolerance.
    // Tested before the line search, which cannot make progress at round-off level (and
    // whose energy test is blind to dead moments, which have no potential).
    if (newton_step_size(dq, L) < settings.tolerance) {
      apply_pose_increment(model, state, dq);
      compute_forces(model, state, f);
      ++stats.force_evaluations;
      return true;
    }
    // Limit the step so that no rotation jumps by more than 1 rad in one iteration.
    double largest_turn = 0;
    for (int i = 0; i + 5 < dq.size(); i += 6) {
      largest_turn = std::max(largest_turn, dq.segment<3>(i + 3).norm());
    }
    double alpha = std::min(1.0, 1.0 / std::max(largest_turn, 1e-300));
    // Backtracking: accept a sufficient decrease of the potential energy (the natural merit
    // for conservative structures) or of the residual (follower loads, indefinite K).
    // Dead moments have no potential, but along this line each body turns about a fixed
    // axis, so their work is exactly linear in alpha and joins the merit. A trial that fails
    // is tried again with its translations balanced for its rotations
    // (solvers/translation_solve.hpp) before the step is halved: the joints' second-order
    // opening otherwise dominates both merits and the steps creep (the alpha = 2 cantilever
    // took ~600 iterations, now 5). Only then, and not on a drive path (stall_iteration > 0),
    // whose short steps near contact it turned onto other branches: the translations' Newton
    // step can press plates together that the plain step keeps apart (zigzag condition 3:
    // 3 478 -> 23 355 iterations, condition 4 stopped).
    const double slope = -g.dot(dq);  // dU/dalpha at alpha = 0
    const double moment_power = dead_moment_work(model, state, dq);
    const State base = state;
    const double u0 = f.potential_energy;
    BodyForces trial;
    double best_r = INFINITY;
    State best = base;
    // Neither merit sees a plate carried through another before their contact switched on
    // (a soft mode where contacts start at zero depth: a Newton step of hundreds of rad, cut
    // to 1 rad above). Checked for long trials only, which can jump a layer; such a trial is
    // neither accepted nor kept as the best.
    const auto jumps_a_layer = [&](double a) {
      return a * largest_turn > kLongTurn && tunnelled(model, state);
    };
    // Sufficient decrease of the trial in `state` with forces `trial`; keeps the best residual.
    const auto acceptable = [&](double a) {
      const double r = residual_norm(model, trial);
      const double u = trial.potential_energy - a * moment_power;
      const bool energy_ok = slope < 0 && u <= u0 + 1e-4 * a * slope;
      if (r < best_r && !jumps_a_layer(a)) best_r = r, best = state;
      return energy_ok || r <= (1 - 1e-4 * a) * r0;
    };
    // Where the whole step is refused, load stepping (not a drive path: as above) tries a
    // short step closed onto the mechanism (solvers/stiff_projection.hpp) before halving: on
    // a closed loop of facets the halvings otherwise creep (the lab cone's fold: 2 041 Newton
    // iterations against 151).
    const auto projected = [&] {
      const double a = std::min(alpha, kProjectedTurn / std::max(largest_turn, 1e-300));
      state = base;
      apply_pose_increment(model, state, a * dq);
      const auto residual = [&](const BodyForces& b) { return residual_norm(model, b); };
      return project_on_stiff_directions(model, state, trial, stats, r0, residual) &&
             acceptable(a) && !jumps_a_layer(a);
    };
    bool accepted = false;
    for (int ls = 0; ls < 10 && !accepted; ++ls, alpha *= 0.5) {
      state = base;
      apply_pose_increment(model, state, alpha * dq);
      compute_forces(model, state, trial);
      ++stats.force_evaluations;
      accepted = acceptable(alpha) ||
                 (stall_iteration == 0 && solve_translations(model, state, trial, stats) &&
                  acceptable(alpha));
      if (accepted && jumps_a_layer(alpha)) accepted = false;
      if (!accepted && ls == 0 && stall_iteration == 0) accepted = projected();
    }
    if (!accepted) state = best;
  }
  return false;
}

// One pseudo-time step of dynamic relaxation from the current poses q_n with velocity v
// (implicit Euler on the undamped structure):
//   M (q - q_n - h v) / h^2 = F(q)
// solved by Newton on the matrix M / h^2 - dF/dq. For small h the matrix is positive
// definite even where the stiffness is not (past a limit point), so the step exists. On
// success `moved` holds q - q_n (no merit test, which would sit at round-off level for small
// steps).
bool relaxation_step(const Model& model, State& state, const Eigen::SparseMatrix<double>& M,
                     double h, const Eigen::VectorXd& v, const SolverSettings& settings,
                     BodyForces& f, SolverStats& stats, Eigen::VectorXd& moved) {
  ForceJacobian jac;
  jac.with_velocity = false;
  const double L = std::max(model.sheet.length, 1e-3);
  const Eigen::SparseMatrix<double> M_h = M / (h * h);
  moved = Eigen::VectorXd::Zero(model.num_dofs);
  for (int it = 0; it < newton_iterations(settings); ++it) {
    compute_forces(model, state, f, &jac);
    ++stats.force_evaluations;
    ++stats.jacobian_evaluations;
    ++stats.newton_iterations;
    const Eigen::VectorXd res = generalized_forces(model, f) - M_h * (moved - h * v);
    Eigen::VectorXd dq;
    if (!res.allFinite() || !solve_newton_system(model, state, M_h - jac.dq, res, dq) ||
        !dq.allFinite()) {
      return false;
    }
    // A step that turns a body by more than 0.1 rad is outside the linearisation: shorter h.
    if (newton_step_size(dq, L) > 0.1) return false;
    apply_pose_increment(model, state, dq);
    moved += dq;
    if (newton_step_size(dq, L) < settings.tolerance) return true;
  }
  return false;
}

// Where the equilibrium path ends at a limit point (the strip snaps to another branch, as the
// real one does under the slowly turned crank) or at a kink of the contact force, Newton
// finds no nearby equilibrium. Dynamic relaxation then lets the strip move under its
// unbalanced forces with kinetic damping (the velocity is zeroed whenever the forces turn
// against it, i.e. at each peak of the kinetic energy), in pseudo-time steps h that grow on
// success, until Newton converges from where it has arrived.
// On a drive path (`on_path`) the settling steps commit the contact history (below); crease
// openings wait for the equilibrium at the end, which the caller commits.
bool settle(const Model& model, State& state, const SolverSettings& settings, double fscale,
            BodyForces& f, SolverStats& stats, int stall_iteration, bool on_path) {
  const Eigen::SparseMatrix<double> M = mass_matrix(model, state);
  constexpr double kFirstStep = 1e-4, kNewtonStep = 1.0, kSmallestStep = 1e-9;  // s
  constexpr int kMaxSteps = 1000;
  double h = kFirstStep;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(model.num_dofs), moved;
  for (int k = 0; k < kMaxSteps; ++k) {
    const State base = state;
    if (h >= kNewtonStep) {
      // Once the pseudo step is this long the mass term no longer matters: finish with Newton.
      if (solve_equilibrium(model, state, settings, fscale, f, stats, stall_iteration)) return true;
      state = base;
      h = 0.25 * kNewtonStep;
      continue;
    }
    if (relaxation_step(model, state, M, h, v, settings, f, stats, moved)) {
      // The snap the settling steps stand for is contact history (sides, anchors), with its
      // pseudo-velocities: a contact point sliding through the snap stays sliding, as in a
      // dynamic pull, instead of re-sticking at every pseudo step (the statics' velocities
      // are zero), and the sides keep the plates from passing through each other. Crease
      // openings are not: the pseudo-time swing of a crease past an opening threshold is the
      // relaxation's own (it has no damping but the kinetic one), not the structure's.
      v = moved / h;
      commit_joint_rotations(model, state);  // the steps may carry a joint through pi
      if (on_path) {
        set_velocity(model, state, v);
        commit_contact_history(model, state);
        set_velocity(model, state, Eigen::VectorXd::Zero(model.num_dofs));
      }
      if (residual_norm(model, f) <= settings.tolerance * fscale) return true;
      if (generalized_forces(model, f).dot(v) < 0) v.setZero();
      h *= 2;
    } else {
      state = base;
      h *= 0.25;
      if (h < kSmallestStep) return false;
    }
  }
  return false;
}

constexpr int kPathIterations = 12;  // Newton iterations per step along a drive path
constexpr int kPathStallIteration = 4;

// Moves a parameter (load scale or drive displacement) from a to b in adaptive increments.
// `dx` is the first increment tried and, on return, the last one that worked (so that the
// next interval starts from it). `stall_iteration` as for solve_equilibrium. `on_path`: the
// equilibria are states the structure passes through (a drive path), committed as history;
// otherwise (load stepping) they are the solver's own way to the end, and history is left
// to the caller.
template <class Setter>
void continuation(const Model& model, State& state, const SolverSettings& settings, double fscale,
                  double a, double b, double& dx, Setter set, const char* what, BodyForces& f,
                  SolverStats& stats, bool on_path, int stall_iteration = 0) {
  double x = a;
  dx = (b > a) ? std::min(dx, b - a) : std::max(dx, b - a);
  const double dx_min = std::abs(b - a) * 1e-6;
  constexpr double kJump = 1e-2;  // of the interval: how far past a limit point settle starts
  while ((b - x) * (b > a ? 1 : -1) > 1e-12 * std::abs(b - a)) {
    require_step_advances(x, dx, std::string("static solver, ") + what);
    const double x_try = (b > a) ? std::min(b, x + dx) : std::max(b, x + dx);
    const State start = state;
    set(state, x_try);
    if (solve_equilibrium(model, state, settings, fscale, f, stats, stall_iteration) &&
        !tunnelled(model, state)) {
      // Every equilibrium on a drive path is history: crease openings, friction anchors and
      // the side each contact point is on follow the path, not only the output points.
      if (on_path) commit_history(model, state);
      x = x_try;
      dx *= 1.5;
      if ((b > a ? dx > (b - a) : dx < (b - a))) dx = b - a;
      continue;
    }
    state = start;
    ++stats.rejected_steps;
    dx *= 0.25;
    if (std::abs(dx) < dx_min) {
      // The branch ends (or the force has a kink) just past x: step beyond it by a small but
      // finite amount and let the strip settle onto the equilibrium it reaches there.
      const double x_jump =
          (b > a) ? std::min(b, x + kJump * (b - a)) : std::max(b, x + kJump * (b - a));
      set(state, x_jump);
      if (settle(model, state, settings, fscale, f, stats, stall_iteration, on_path) &&
          !tunnelled(model, state)) {
        if (on_path) commit_history(model, state);
        ++stats.settles;
        x = x_jump;
        dx = kJump * (b - a);
        continue;
      }
      state = start;
      throw DivergenceError(fmt::format(
          "static solver: no equilibrium found beyond {} = {:.6g} (increment below {:.3g}); "
          "most strained {}",
          what, x, dx_min, most_strained_element(model, state)));
    }
  }
}

// Whether the model's plate cells include corrections to the joints' bending (they carry the
// Poisson coupling of plates cut from patterns; docs/solvers.md, "Plates: the corrections
// last").
bool has_plate_corrections(const Model& model) {
  for (const PlateCellDef& c : model.plate_cells) {
    if (c.correction) return true;
  }
  return false;
}

// Memory of a drive path at an output: the path steps done and the continuation increment
// the next one starts with, so that a resumed run continues exactly (docs/state-file.md).
SolverMemory path_memory(const State& state, long steps_done, double ds) {
  SolverMemory m;
  m.dt = ds;
  m.steps = steps_done;
  m.t = state.t;
  return m;
}

// A drive path resumed from a checkpoint: its memory belongs to this state.
bool resumes_path(const State& state) {
  return state.solver.t == state.t && state.solver.dt > 0 && state.solver.steps >= 0;
}

// Quasi-static pull from path step `done` on: one equilibrium per drive step; t records the
// drive displacement. Along the pull Newton converges in a handful of iterations where it
// converges at all: a step that needs more, or stalls, is cut (cheaper than iterating on, and
// the cut steps converge fast). Long Newton runs also wander onto other branches than the
// slow pull's (docs/zigzag.md, "Status").
void drive_path(const Model& model, State& state, const SolverSettings& settings, double fscale,
                long done, double ds, const OutputCallback& on_output,
                const ProgressCallback& on_progress, BodyForces& f, SolverStats& stats) {
  const DriveDef& d0 = model.drives[0];
  const long n = solver_step_count(d0.travel, d0.step, "static solver (drive path)");
  SolverSettings path_settings = settings;
  path_settings.max_iterations = std::min(newton_iterations(settings), kPathIterations);
  for (long k = done + 1; k <= n; ++k) {
    const double s_from = state.drive_s[0];
    const double s_to = std::min(d0.travel, k * d0.step);
    continuation(
        model, state, path_settings, fscale, s_from, s_to, ds,
        [&](State& s, double x) {
          for (size_t i = 0; i < model.drives.size(); ++i) {
            const DriveDef& d = model.drives[i];
            s.drive_s[i] = std::min(d.travel, x * (d.step / d0.step));
          }
          s.t = x;
        },
        "drive displacement", f, stats, true, kPathStallIteration);
    commit_history(model, state);
    ++stats.steps;
    state.solver = path_memory(state, k, ds);
    on_output(state, f);
    on_progress({static_cast<double>(k) / n, state.t, s_to - s_from, &stats});
  }
}

}  // namespace

void run_static(const Model& model, State& state, const SolverSettings& settings,
                const OutputCallback& on_output, const ProgressCallback& on_progress,
                SolverStats& stats) {
  const double fscale = force_scale(model);
  set_quasi_static(state, true);
  for (Vec3& v : state.v_W) v.setZero();
  for (Vec3& w : state.w_W) w.setZero();
  BodyForces f;
  const bool path = has_drive_path(model);
  if (path && resumes_path(state)) {
    compute_forces(model, state, f);
    on_output(state, f);  // the checkpoint's output (a resumed run does not record it again)
    drive_path(model, state, settings, fscale, state.solver.steps, state.solver.dt, on_output,
               on_progress, f, stats);
    return;
  }
  // Loads first, by load stepping from zero. The load steps' equilibria are the solver's
  // way to the loaded equilibrium of the initial state, not states the structure passes
  // through (started from zero load, a structure set up near its loaded equilibrium swings
  // back towards its rest shape): only the loaded equilibrium is committed. Plate corrections
  // come last: the loads are stepped on the joints alone, then the corrections are switched on
  // at the full load (a continuation in their scale). A thin plate's Poisson coupling, which
  // they carry, makes the way from flat non-convex (the linear step's anticlastic curvature,
  // which the membrane forbids); from the plate bent without it Newton takes a few iterations
  // (the 200 mm paper sheet at 16 x 16: 134 -> 21 iterations; docs/solvers.md).
  const double lambda_end = state.load_scale;
  state.load_scale = 0;
  state.t = 0;
  commit_history(model, state, true);  // the initial state is one the structure is in
  compute_forces(model, state, f);
  if (!path) on_output(state, f);
  double dlambda = lambda_end / std::max(1, settings.load_steps);
  const bool corrections_last = has_plate_corrections(model);
  if (corrections_last) state.plate_correction_scale = 0;
  continuation(
      model, state, settings, fscale, 0.0, lambda_end, dlambda,
      [&](State& s, double x) {
        s.load_scale = x;
        s.t = x;
        if (!path && x < lambda_end) on_progress({x / lambda_end, x, 0, &stats});  // long solves
      },
      "load scale", f, stats, false);
  if (corrections_last) {
    double ds = 1;  // all at once first; cut where Newton fails
    continuation(
        model, state, settings, fscale, 0.0, 1.0, ds,
        [](State& s, double x) { s.plate_correction_scale = x; }, "plate correction scale", f,
        stats, false);
  }
  commit_history(model, state);
  ++stats.steps;
  if (!path) {
    on_output(state, f);
    on_progress({1.0, state.t, 0, &stats});
    return;
  }
  state.t = 0;
  state.solver = path_memory(state, 0, model.drives[0].step);
  on_output(state, f);
  drive_path(model, state, settings, fscale, 0, model.drives[0].step, on_output, on_progress, f,
             stats);
}

}  // namespace finseg
