// Cost of the cantilever's building blocks against the number of segments: one force
// evaluation, forces with the exact Jacobian, one explicit step and one static solve.
// Each should grow linearly (the static solve: per Newton iteration). Reports the fitted
// complexity.
#include <benchmark/benchmark.h>

#include "generators/cantilever.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace {

// The slender strip of the validation tests (L / t = 1000) under alpha = P L^2 / EI.
Model cantilever(int segments, double alpha) {
  CantileverSpec s;
  s.segments = segments;
  s.tip_force = Vec3(0, 0, -alpha * bending_rigidity(s) / (s.length * s.length));
  return build_cantilever_model(s);
}

void BM_Forces(benchmark::State& st) {
  const Model m = cantilever(static_cast<int>(st.range(0)), 2);
  const State s = initial_state(m);
  BodyForces f;
  for (auto _ : st) {
    compute_forces(m, s, f);
    benchmark::DoNotOptimize(f.potential_energy);
  }
  st.SetComplexityN(st.range(0));
}

// Closed-form element Jacobians (range 1 = 0) or their automatic-differentiation oracle
// (range 1 = 1), poses and velocities.
void BM_ForcesAndJacobian(benchmark::State& st) {
  const Model m = cantilever(static_cast<int>(st.range(0)), 2);
  const State s = initial_state(m);
  BodyForces f;
  ForceJacobian jac;
  jac.autodiff = st.range(1) != 0;
  for (auto _ : st) {
    compute_forces(m, s, f, &jac);
    benchmark::DoNotOptimize(jac.dq.nonZeros());
  }
  st.SetComplexityN(st.range(0));
}

// 10 explicit steps per iteration at a fixed step (no stability estimate in the loop).
void BM_ExplicitStep(benchmark::State& st) {
  const Model m = cantilever(static_cast<int>(st.range(0)), 2);
  SolverSettings set;
  set.kind = SolverKind::Explicit;
  set.dt = 1e-9;
  set.t_end = 10 * set.dt;
  set.output_interval = set.t_end;
  for (auto _ : st) {
    State s = initial_state(m);
    run_solver(m, s, set, {});
  }
  st.counters["s_per_step"] = benchmark::Counter(
      10, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  st.SetComplexityN(st.range(0));
}

// Static solve of the large deflection alpha = 2 from the flat state.
void BM_StaticSolve(benchmark::State& st) {
  const Model m = cantilever(static_cast<int>(st.range(0)), 2);
  SolverSettings set;
  set.kind = SolverKind::Static;
  long iterations = 0;
  for (auto _ : st) {
    State s = initial_state(m);
    iterations = run_solver(m, s, set, {}).newton_iterations;
  }
  st.counters["newton_iterations"] = static_cast<double>(iterations);
  st.SetComplexityN(st.range(0));
}

BENCHMARK(BM_Forces)->RangeMultiplier(4)->Range(16, 4096)->Complexity();
BENCHMARK(BM_ForcesAndJacobian)
    ->ArgsProduct({benchmark::CreateRange(16, 4096, 4), {0, 1}})
    ->Complexity();
BENCHMARK(BM_ExplicitStep)->RangeMultiplier(4)->Range(16, 4096)->Complexity();
BENCHMARK(BM_StaticSolve)
    ->RangeMultiplier(4)
    ->Range(16, 256)
    ->Unit(benchmark::kMillisecond)
    ->Complexity();

}  // namespace
}  // namespace finseg

BENCHMARK_MAIN();
