// The cantilever benchmark table of BENCHMARKS.md: for each number of segments and each
// solver, steps, wall time (per simulated second for the dynamic solvers, per solve for the
// static one), cost per step and segment, and peak memory. Every case runs in a child
// process, so its peak resident set (from wait4) is its own.
// Usage: bench_cantilever_table [segments...]   (default 16 64 256 1024 4096)
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "generators/cantilever.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace {

struct Case {
  int segments;
  SolverKind kind;
};

struct Result {
  long steps = 0, newton = 0;
  double simulated_s = 0, wall_s = 0;
  char status[16] = "";
};

const char* name(SolverKind k) {
  return k == SolverKind::Explicit ? "explicit" : k == SolverKind::Implicit ? "implicit" : "static";
}

// The slender strip of the validation tests (0.1 m x 20 mm x 0.1 mm) under the tip load
// alpha = P L^2 / EI = 2, suddenly applied (dynamic solvers) or in one static solve.
Result run_case(const Case& c) {
  CantileverSpec s;
  s.segments = c.segments;
  s.tip_force = Vec3(0, 0, -2 * bending_rigidity(s) / (s.length * s.length));
  const Model m = build_cantilever_model(s);
  State state = initial_state(m);
  SolverSettings set;
  set.kind = c.kind;
  if (c.kind == SolverKind::Implicit) {
    set.t_end = 2e-2;
    set.output_interval = set.t_end / 20;
    set.rtol = 1e-3;
  }
  Result r;
  if (c.kind == SolverKind::Explicit) {
    // 2000 steps at the automatic (stability-limited) step; the first call (t_end = 0)
    // only computes that step.
    SolverSettings probe = set;
    probe.t_end = 0;
    State s0 = state;
    const double dt = run_solver(m, s0, probe, {}).smallest_step;
    set.dt = dt;
    set.t_end = 2000 * dt;
    set.output_interval = set.t_end;
  }
  const SolverStats st = run_solver(m, state, set, {});
  r.steps = st.steps;
  r.newton = st.newton_iterations;
  r.simulated_s = c.kind == SolverKind::Static ? 0 : set.t_end;
  r.wall_s = st.wall_seconds;
  std::snprintf(r.status, sizeof r.status, "%s", st.status.c_str());
  return r;
}

// Runs one case in a child process; returns its result and its peak RSS in MiB.
bool run_in_child(const Case& c, Result& r, double& peak_mib) {
  int fd[2];
  if (pipe(fd) != 0) return false;
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    close(fd[0]);
    const Result res = run_case(c);
    const ssize_t n = write(fd[1], &res, sizeof res);
    _exit(n == static_cast<ssize_t>(sizeof res) ? 0 : 1);
  }
  close(fd[1]);
  const ssize_t n = read(fd[0], &r, sizeof r);
  close(fd[0]);
  int status = 0;
  rusage ru{};
  wait4(pid, &status, 0, &ru);
  peak_mib = ru.ru_maxrss / 1024.0;  // Linux: KiB
  return n == static_cast<ssize_t>(sizeof r) && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace
}  // namespace finseg

int main(int argc, char** argv) {
  using namespace finseg;
  std::vector<int> sizes;
  for (int i = 1; i < argc; ++i) sizes.push_back(std::atoi(argv[i]));
  if (sizes.empty()) sizes = {16, 64, 256, 1024, 4096};
  std::printf(
      "| segments | solver | steps | Newton iterations | simulated time (s) | wall (s) | wall per "
      "simulated s "
      "or per solve (s) | wall per step (us) | per step and segment (ns) | peak RSS (MiB) | "
      "status |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int n : sizes) {
    for (SolverKind k : {SolverKind::Explicit, SolverKind::Implicit, SolverKind::Static}) {
      Result r;
      double peak = 0;
      if (!run_in_child({n, k}, r, peak)) {
        std::printf("| %d | %s | child process failed |\n", n, name(k));
        continue;
      }
      const double per_sim = k == SolverKind::Static ? r.wall_s : r.wall_s / r.simulated_s;
      const double per_step = r.wall_s / std::max(1L, r.steps);
      std::printf("| %d | %s | %ld | %ld | %.3g | %.3g | %.3g | %.3g | %.3g | %.1f | %s |\n", n,
                  name(k), r.steps, r.newton, r.simulated_s, r.wall_s, per_sim, 1e6 * per_step,
                  1e9 * per_step / n, peak, r.status);
      std::fflush(stdout);
    }
  }
  return 0;
}
