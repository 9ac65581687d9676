// Issue 12 benchmark (a), BENCHMARKS.md "Implicit schemes": the 200 x 40 x 0.1 mm paper strip
// (E = 4 GPa, 800 kg/m^3, q L^3 / EI = 18.8), clamped at one end, falling from flat under its
// own weight with no damping. For each scheme, the loosest rtol (from --start-ga / --start-be,
// default 1e-3, down by ~3x to 1e-7) whose tip stays within 1e-3 L of a converged reference
// at t = 0.25, 0.5 and 1 s; every rtol tried is printed (steps, Newton iterations, wall and
// CPU seconds per simulated second). The reference is generalized-alpha at --ref (default
// 1e-8), checked against --check (default 1e-7): their difference is printed, so that a
// cheaper reference shows it is converged.
// Usage:
//   bench_implicit_schemes [--ref R] [--check R] [--start-ga R] [--start-be R]
//                          [--schemes ga|be|both] [--atol A] [segments...]   (default 40 160
//                          640; --atol: absolute tolerance, m and rad, of every run, default
//                          the solver's 1e-7, which bounds the local error below rtol ~1e-6)
//   bench_implicit_schemes --single ga|be RTOL segments...: one run per segment count, its
//     counts, times and the three tip positions (m, full precision), for sweeps split over
//     processes; compare their tips with a reference run's by hand.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
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

double g_atol = 0;  // --atol: absolute tolerance of every run (0: the solver's default)

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
  if (g_atol > 0) set.atol = g_atol;
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

namespace {

// Parses a positive rtol for option `name`, or exits naming the option and the allowed range.
double parse_rtol(const char* name, const char* text) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(v > 0 && v < 1)) {
    std::fprintf(stderr, "bench_implicit_schemes: %s must be a number in (0, 1), got '%s'\n", name,
                 text);
    std::exit(2);
  }
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace finseg;
  std::vector<int> segs;
  double ref_rtol = 1e-8, check_rtol = 1e-7, start_ga = 1e-3, start_be = 1e-3;
  bool run_ga = true, run_be = true;
  const char* single = nullptr;  // --single: scheme name
  double single_rtol = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if ((a == "--ref" || a == "--check" || a == "--atol" || a == "--start-ga" ||
         a == "--start-be" || a == "--schemes") &&
        !has_value) {
      std::fprintf(stderr, "bench_implicit_schemes: %s needs a value\n", a.c_str());
      return 2;
    }
    if (a == "--atol") {
      g_atol = parse_rtol("--atol", argv[++i]);
    } else if (a == "--single") {
      if (i + 2 >= argc) {
        std::fprintf(stderr, "bench_implicit_schemes: --single needs a scheme and an rtol\n");
        return 2;
      }
      single = argv[++i];
      if (std::strcmp(single, "ga") != 0 && std::strcmp(single, "be") != 0) {
        std::fprintf(stderr, "bench_implicit_schemes: --single scheme must be ga or be\n");
        return 2;
      }
      single_rtol = parse_rtol("--single rtol", argv[++i]);
    } else if (a == "--ref") {
      ref_rtol = parse_rtol("--ref", argv[++i]);
    } else if (a == "--check") {
      check_rtol = parse_rtol("--check", argv[++i]);
    } else if (a == "--start-ga") {
      start_ga = parse_rtol("--start-ga", argv[++i]);
    } else if (a == "--start-be") {
      start_be = parse_rtol("--start-be", argv[++i]);
    } else if (a == "--schemes") {
      const std::string v = argv[++i];
      if (v != "ga" && v != "be" && v != "both") {
        std::fprintf(stderr, "bench_implicit_schemes: --schemes must be ga, be or both\n");
        return 2;
      }
      run_ga = v != "be";
      run_be = v != "ga";
    } else {
      char* end = nullptr;
      const long n = std::strtol(argv[i], &end, 10);
      if (end == argv[i] || *end != '\0' || n < 2 || n > 100000) {
        std::fprintf(stderr,
                     "bench_implicit_schemes: segments must be an integer in [2, 100000], got "
                     "'%s'\n",
                     argv[i]);
        return 2;
      }
      segs.push_back(static_cast<int>(n));
    }
  }
  if (segs.empty()) segs = {40, 160, 640};
  if (single) {
    const bool ga = std::strcmp(single, "ga") == 0;
    for (int n : segs) {
      const Run r = run(n, ga ? ImplicitScheme::GeneralizedAlpha : ImplicitScheme::BackwardEuler,
                        single_rtol);
      std::printf("%d %s %.0e steps %ld rejected %ld newton %ld wall %.4g cpu %.4g tips", n, single,
                  single_rtol, r.stats.steps, r.stats.rejected_steps, r.stats.newton_iterations,
                  r.wall, r.cpu);
      for (const Vec3& t : r.tips) std::printf(" %.17g %.17g %.17g", t.x(), t.y(), t.z());
      std::printf("\n");
      std::fflush(stdout);
    }
    return 0;
  }
  // The sweep: start, start / ~3, ... down to 1e-7.
  auto sweep = [](double start) {
    std::vector<double> rtols;
    for (double r : {1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6, 3e-7, 1e-7}) {
      if (r <= start * (1 + 1e-9)) rtols.push_back(r);
    }
    return rtols;
  };
  std::vector<ImplicitScheme> schemes;
  if (run_ga) schemes.push_back(ImplicitScheme::GeneralizedAlpha);
  if (run_be) schemes.push_back(ImplicitScheme::BackwardEuler);
  std::printf(
      "| segments | scheme | rtol | tip error / L | steps | rejected | Newton | wall per "
      "simulated s | CPU per simulated s |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- "
      "|\n");
  for (int n : segs) {
    const Run ref = run(n, ImplicitScheme::GeneralizedAlpha, ref_rtol);
    std::printf("| %d | reference | %.0e | | %ld | %ld | %ld | %.3g s | %.3g s |\n", n, ref_rtol,
                ref.stats.steps, ref.stats.rejected_steps, ref.stats.newton_iterations, ref.wall,
                ref.cpu);
    std::fflush(stdout);
    const Run check = run(n, ImplicitScheme::GeneralizedAlpha, check_rtol);
    std::printf(
        "| %d | check of the reference | %.0e | %.1e (vs %.0e) | %ld | %ld | %ld | %.3g s | %.3g s "
        "|\n",
        n, check_rtol, worst(ref, check), ref_rtol, check.stats.steps, check.stats.rejected_steps,
        check.stats.newton_iterations, check.wall, check.cpu);
    std::fflush(stdout);
    for (ImplicitScheme sch : schemes) {
      const char* name =
          sch == ImplicitScheme::GeneralizedAlpha ? "generalized-alpha 0.8" : "backward Euler";
      bool found = false;
      const bool ga = sch == ImplicitScheme::GeneralizedAlpha;
      for (double rtol : sweep(ga ? start_ga : start_be)) {
        const Run r = run(n, sch, rtol);
        const double e = worst(r, ref);
        std::printf("| %d | %s | %.0e | %.1e%s | %ld | %ld | %ld | %.3g s | %.3g s |\n", n, name,
                    rtol, e, e < 1e-3 ? " (passes)" : "", r.stats.steps, r.stats.rejected_steps,
                    r.stats.newton_iterations, r.wall, r.cpu);
        std::fflush(stdout);
        if (e < 1e-3) {
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
