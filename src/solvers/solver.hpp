// The one interface shared by the explicit, implicit and static solvers.
#pragma once

#include <functional>
#include <string>

#include "elements/assemble.hpp"
#include "model/model.hpp"
#include "model/state.hpp"
#include "solvers/linear_solve.hpp"

namespace finseg {

enum class SolverKind { Explicit, Implicit, Static };

/// Time integration scheme of the implicit solver (docs/solvers.md).
enum class ImplicitScheme {
  BackwardEuler,     ///< first order, strongly dissipative, never gains energy
  GeneralizedAlpha,  ///< second order (Chung-Hulbert), dissipation set by rho_inf
};

struct SolverSettings {
  SolverKind kind = SolverKind::Static;
  double t_end = 1.0;            ///< dynamic solvers: simulated time, s
  double output_interval = 0.0;  ///< s between recorded outputs (0: every 1/100 of t_end)
  double dt = 0.0;       ///< explicit: fixed step (0: automatic from the highest frequency);
                         ///< implicit: first step
  double dt_min = 1e-9;  ///< implicit: smallest step before giving up, s
  double dt_max = 0.0;   ///< implicit: largest step (0: output_interval)
  double rtol = 1e-4;    ///< implicit: relative local error tolerance
  double atol = 1e-7;    ///< implicit: absolute local error tolerance (m and rad)
  ImplicitScheme scheme = ImplicitScheme::BackwardEuler;  ///< implicit: integration scheme
  /// implicit generalized-alpha: spectral radius at infinite frequency, 0..1 (1: no
  /// numerical dissipation; 0.8 damps unresolved stiff modes by 20 % a step and keeps the
  /// damping ratio of resolved modes below 1e-3 at h omega = 0.2).
  double rho_inf = 0.8;
  int load_steps = 1;  ///< static: initial number of load increments
  /// static/implicit: Newton iterations per solve; 0: the solver's own (newton_iterations())
  int max_iterations = 0;
  double tolerance = 1e-9;  ///< static: residual tolerance relative to the load scale
  /// implicit: keep Newton's factored iteration matrix across iterations and steps while it
  /// contracts (modified Newton, docs/solvers.md); false: a new one every iteration.
  bool jacobian_reuse = true;
  bool krylov_steps = true;   ///< implicit, with jacobian_reuse: GMRES on a kept factor first
  int jacobian_max_age = 20;  ///< implicit: Newton iterations one kept matrix serves at most
  /// implicit: Newton stops when its pose correction (and with a kept matrix the error bound
  /// left after it) is below this fraction of the local error tolerance (docs/solvers.md)
  double newton_tolerance = 1e-3;
  /// implicit: the local error and Newton's test measured as the largest displacement of a
  /// segment's points (rotations times its radius, displacement_weights) instead of in m and
  /// rad, where a small segment's rotation counts as much as a metre (docs/solvers.md, "Step
  /// control").
  bool error_at_points = false;
};

/// Newton iterations per solve: `max_iterations`, else 10 for the implicit solver (a harder
/// solve costs less as a step cut by 4 than as more iterations and matrices: BENCHMARKS.md,
/// "Newton iterations per step") and 50 for the static one.
inline int newton_iterations(const SolverSettings& s) {
  if (s.max_iterations > 0) return s.max_iterations;
  return s.kind == SolverKind::Implicit ? 10 : 50;
}

/// Counters and timing reported in summary.json.
struct SolverStats {
  long steps = 0;  ///< accepted steps or converged equilibria
  long rejected_steps = 0;
  long newton_failures = 0;  ///< implicit: of the rejected steps, those whose Newton failed
  long newton_iterations = 0;
  long force_evaluations = 0;
  long jacobian_evaluations = 0;
  long factorizations = 0;     ///< implicit: factorizations of Newton's iteration matrix
  long krylov_steps = 0;       ///< implicit: new matrices solved by GMRES on a kept factor instead
  long krylov_iterations = 0;  ///< implicit: GMRES iterations, those of failed tries included
  long secant_solves = 0;      ///< implicit: Newton solves gone on with friction's secant
  long settles = 0;            ///< static: limit points passed by pseudo-transient continuation
  double smallest_step = 0, largest_step = 0;
  double wall_seconds = 0;
  /// The run's sparse solves (analyses, Cholesky and LU factorizations and their seconds).
  LinearSolveCounters linear;
  std::string status = "ok";  ///< "ok" or "diverged"
  std::string message;        ///< diagnosis when diverged
};

/// Called at t = 0, at each output time and at the end, with the forces at that state (a stop
/// request between outputs ends the run without one: stop_request.hpp).
using OutputCallback = std::function<void(const State&, const BodyForces&)>;
/// Where a running solver is, for progress displays.
struct SolverProgress {
  double fraction = 0;                 ///< of the run done, 0..1
  double t = 0;                        ///< simulated time, s (static: the load or drive parameter)
  double step = 0;                     ///< the last accepted step, s (0 where there is none)
  const SolverStats* stats = nullptr;  ///< the counts so far
};
/// Called after every accepted step (dynamic solvers) or equilibrium (static).
using ProgressCallback = std::function<void(const SolverProgress&)>;

/// Runs the chosen solver from `state` to the end. A divergence is reported in the
/// returned stats (status "diverged", message names time, element and quantity) and
/// leaves `state` at the last good point.
SolverStats run_solver(const Model& model, State& state, const SolverSettings& settings,
                       const OutputCallback& on_output, const ProgressCallback& on_progress = {});

/// Natural frequencies (Hz, ascending) of small vibrations about `state`, which should be
/// an equilibrium: generalized eigenproblem K x = w^2 M x on the free DOFs.
std::vector<double> natural_frequencies(const Model& model, const State& state, int count);

}  // namespace finseg
