// Issue 12 (c) and (d) as a table: a 200 x 200 x 0.1 mm paper sheet (E = 3 GPa, nu = 0.3,
// 800 kg/m^3) cut into n x n segments, clamped along one edge, under its own weight, from the
// flat state with default settings: a static solve, or one implicit step (backward Euler or
// generalized-alpha) of length dt. Prints the Newton iterations, factorizations, refinement
// steps, wall and CPU time, peak resident memory and where the time goes (force and Jacobian
// evaluations, estimated from one timed evaluation of each; symbolic analyses, numeric
// factorizations and the rest of the linear solves, from linear_solve_counters()).
// Usage: bench_sheet_scale [--dt S] [case:n ...]   case: static, euler or alpha
// (default: static:100 euler:316 alpha:316; dt default 1e-3 s). Peak memory is the process'
// so far: run one case per process to measure each.
#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

#include "generators/sheet.hpp"
#include "solvers/linear_solve.hpp"
#include "solvers/solver.hpp"

namespace {

using namespace finseg;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// User + system CPU seconds of the process so far (on a loaded machine the wall time
// includes waiting for a core).
double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double peak_rss_gb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1048576.0;  // kB on Linux
}

// Seconds of one force evaluation with (jacobian = true) or without its Jacobian at `state`.
double evaluation_seconds(const Model& m, const State& state, bool jacobian) {
  BodyForces f;
  ForceJacobian jac;
  const auto t = Clock::now();
  compute_forces(m, state, f, jacobian ? &jac : nullptr);
  return since(t);
}

void run_case(const std::string& kind, int n, double dt) {
  const Model m = clamped_paper_sheet(n);
  State state = initial_state(m);
  SolverSettings set;
  if (kind == "static") {
    set.kind = SolverKind::Static;
  } else {
    set.kind = SolverKind::Implicit;
    set.scheme = kind == "alpha" ? ImplicitScheme::GeneralizedAlpha : ImplicitScheme::BackwardEuler;
    set.t_end = set.dt = set.dt_max = set.output_interval = dt;
  }
  linear_solve_counters() = {};
  const double cpu0 = cpu_seconds();
  const SolverStats st = run_solver(m, state, set, {});
  const LinearSolveCounters c = linear_solve_counters();
  const double rss = peak_rss_gb();
  // Forces and Jacobians, as the solvers evaluate them: statics without dv.
  const double t_jac = evaluation_seconds(m, state, true);
  const double t_force = evaluation_seconds(m, state, false);
  const double assembly =
      st.jacobian_evaluations * t_jac + (st.force_evaluations - st.jacobian_evaluations) * t_force;
  double z_min = 0;
  for (const Vec3& p : state.p_W) z_min = std::min(z_min, p.z());
  fmt::print(
      "{:>7} {:>8} {:>8} {:>6} {:>5} {:>6} {:>5} {:>5} {:>4} {:>6} {:>8.2f} {:>8.2f} {:>7.2f} "
      "{:>9.2f} {:>8.2f} {:>8.2f} {:>8.2f} {:>8.2f} {:>10.4g} {}\n",
      kind, n * n, m.num_dofs, st.newton_iterations, st.jacobian_evaluations, c.factorizations,
      c.lu_factorizations, c.indefinite, c.analyses, c.refinements, st.wall_seconds,
      cpu_seconds() - cpu0, rss, assembly, c.analyse_s, c.factor_s,
      c.total_s - c.analyse_s - c.factor_s, st.wall_seconds - assembly - c.total_s, 1e3 * z_min,
      st.status == "ok" ? fmt::format("ok, {} steps, {} rejected", st.steps, st.rejected_steps)
                        : st.message);
}

}  // namespace

int main(int argc, char** argv) {
  double dt = 1e-3;
  std::vector<std::string> cases;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--dt" && i + 1 < argc) {
      dt = std::atof(argv[++i]);
    } else {
      cases.push_back(a);
    }
  }
  if (cases.empty()) cases = {"static:100", "euler:316", "alpha:316"};
  fmt::print(
      "{:>7} {:>8} {:>8} {:>6} {:>5} {:>6} {:>5} {:>5} {:>4} {:>6} {:>8} {:>8} {:>7} {:>9} {:>8} "
      "{:>8} {:>8} {:>8} {:>10} {}\n",
      "case", "segments", "dofs", "newton", "jacs", "factor", "lu", "indef", "anal", "refine",
      "wall_s", "cpu_s", "rss_GB", "forces_s", "analyse", "factor_s", "lsolve_s", "other_s",
      "z_min_mm", "status");
  for (const std::string& c : cases) {
    const auto colon = c.find(':');
    const std::string kind = c.substr(0, colon);
    if (colon == std::string::npos || (kind != "static" && kind != "euler" && kind != "alpha")) {
      fmt::print(stderr, "bench_sheet_scale: case '{}' is not static:n, euler:n or alpha:n\n", c);
      return 2;
    }
    run_case(kind, std::atoi(c.c_str() + colon + 1), dt);
  }
  return 0;
}
