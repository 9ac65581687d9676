// The paper's pull test (Table 1 conditions) as Google Benchmarks: the whole static pull at
// several discretisations, and one pose-only Jacobian evaluation. BENCHMARKS.md, "Folded strip".
#include <benchmark/benchmark.h>

#include "elements/assemble.hpp"
#include "generators/zigzag_conditions.hpp"
#include "probes/pull_test.hpp"

namespace {

using namespace finseg;

// Args: condition (1..4), segments per panel, contact (0/1).
void BM_ZigzagPull(benchmark::State& bs) {
  ZigzagSpec spec = paper_condition(static_cast<int>(bs.range(0)));
  spec.segments_per_panel = static_cast<int>(bs.range(1));
  spec.contact = bs.range(2) != 0;
  const Model m = build_zigzag_model(spec);
  PullResult r;
  for (auto _ : bs) {
    r = run_pull_test(m, {1, 4}, kDefaultBendThreshold);
    benchmark::DoNotOptimize(r.peak_force);
  }
  bs.counters["equilibria"] = static_cast<double>(r.stats.steps);
  bs.counters["newton"] = static_cast<double>(r.stats.newton_iterations);
  bs.counters["ok"] = r.stats.status == "ok" ? 1 : 0;
}
BENCHMARK(BM_ZigzagPull)
    ->ArgsProduct({{1, 2, 3, 4}, {8, 16}, {0}})
    ->Args({1, 32, 0})
    ->Args({1, 8, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

void BM_ZigzagJacobian(benchmark::State& bs) {
  ZigzagSpec spec = paper_condition(1);
  spec.segments_per_panel = static_cast<int>(bs.range(0));
  spec.contact = false;
  const Model m = build_zigzag_model(spec);
  const State st = initial_state(m);
  BodyForces f;
  ForceJacobian jac;
  jac.with_velocity = bs.range(1) != 0;
  for (auto _ : bs) {
    compute_forces(m, st, f, &jac);
    benchmark::DoNotOptimize(jac.dq.nonZeros());
  }
  bs.counters["elements"] = static_cast<double>(m.elements.size());
}
BENCHMARK(BM_ZigzagJacobian)->ArgsProduct({{8, 16}, {0, 1}})->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
