// Issue 12 benchmark (a), BENCHMARKS.md "Implicit schemes": the 200 x 40 x 0.1 mm paper strip
// (E = 4 GPa, 800 kg/m^3, q L^3 / EI = 18.8), clamped at one end, falling from flat under its
// own weight with no damping. For each scheme, the loosest rtol (from 1e-3 down by ~3x) whose
// tip stays within 1e-3 L of a converged reference at t = 0.25, 0.5 and 1 s; steps, Newton
// iterations and wall seconds per simulated second at that rtol. The reference is
// generalized-alpha at rtol 1e-8 (checked against 1e-7: their difference is printed).
// Usage: bench_implicit_schemes [segments...]   (default 40 160 640)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "generators/cantilever.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace {

constexpr double kL = 0.2;

struct Run {
  std::vector<Vec3> tips;  // at 0.25, 0.5, 1 s
  SolverStats stats;
  double wall = 0, cpu = 0;  // s; cpu: this process's CPU time (robust on a shared machine)
};

Run run(int segments, ImplicitScheme scheme, double rtol) {
  CantileverSpec s;
  s.length = kL;
  s.width = 0.04;
  s.thickness = 1e-4;
  s.segments = segments;
  s.gravity = true;
  const Model m = build_cantilever_model(s);
  int tip = -1;
  for (size_t i = 0; i < m.probes.size(); ++i) {
    if (m.probes[i].name == "tip") tip = static_cast<int>(i);
  }
  const ProbeDef& p = m.probes.at(tip);
  State state = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Implicit;
  set.scheme = scheme;
  set.t_end = 1.0;
  set.output_interval = 0.25;
  set.rtol = rtol;
  Run r;
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  r.stats = run_solver(m, state, set, [&](const State& x, const BodyForces&) {
    for (double t : {0.25, 0.5, 1.0}) {
      if (std::abs(x.t - t) < 1e-9) r.tips.push_back(x.p_W[p.body] + x.R_WB[p.body] * p.point_B);
    }
  });
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  return r;
}

double worst(const Run& a, const Run& b) {
  double e = INFINITY;
  if (a.tips.size() == 3 && b.tips.size() == 3) {
    e = 0;
    for (int k = 0; k < 3; ++k) e = std::max(e, (a.tips[k] - b.tips[k]).norm() / kL);
  }
  return e;
}

}  // namespace
}  // namespace finseg

int main(int argc, char** argv) {
  using namespace finseg;
  std::vector<int> segs;
  for (int i = 1; i < argc; ++i) segs.push_back(std::atoi(argv[i]));
  if (segs.empty()) segs = {40, 160, 640};
  const std::vector<double> rtols = {1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6, 3e-7, 1e-7};
  std::printf(
      "| segments | scheme | rtol | tip error / L | steps | rejected | Newton | wall per "
      "simulated s |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (int n : segs) {
    const Run ref = run(n, ImplicitScheme::GeneralizedAlpha, 1e-8);
    const Run check = run(n, ImplicitScheme::GeneralizedAlpha, 1e-7);
    std::printf("| %d | reference | 1e-8 | %.1e (vs 1e-7) | %ld | %ld | %ld | %.3g s | %.3g s |\n",
                n, worst(ref, check), ref.stats.steps, ref.stats.rejected_steps,
                ref.stats.newton_iterations, ref.wall, ref.cpu);
    std::fflush(stdout);
    for (ImplicitScheme sch : {ImplicitScheme::GeneralizedAlpha, ImplicitScheme::BackwardEuler}) {
      const char* name =
          sch == ImplicitScheme::GeneralizedAlpha ? "generalized-alpha 0.8" : "backward Euler";
      bool found = false;
      for (double rtol : rtols) {
        const Run r = run(n, sch, rtol);
        const double e = worst(r, ref);
        if (e < 1e-3) {
          std::printf("| %d | %s | %.0e | %.1e | %ld | %ld | %ld | %.3g s | %.3g s |\n", n, name,
                      rtol, e, r.stats.steps, r.stats.rejected_steps, r.stats.newton_iterations,
                      r.wall, r.cpu);
          found = true;
          break;
        }
      }
      if (!found) std::printf("| %d | %s | - | not reached at rtol 1e-7 | | | | | |\n", n, name);
      std::fflush(stdout);
    }
  }
  return 0;
}
