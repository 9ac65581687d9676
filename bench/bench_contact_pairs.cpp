// Cost of the contact's candidate pairs against the number of segments: a strip folded flat
// into 10 layers (patterns/stack_pattern.hpp) of n x n square cells of 1 mm, 0.1 mm thick,
// every layer on the one below. One call builds the pair rules (vertex classes through the
// force elements, docs/contact.md "Which pairs"), the plates' boxes, the broad phase and the
// rule filter: what every contact evaluation pays before its narrow phase. Expected: n log n.
#include <benchmark/benchmark.h>

#include <memory>

#include "collision/pair_rules.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "patterns/pattern_checks.hpp"
#include "patterns/stack_pattern.hpp"

namespace finseg {
namespace {

Model folded_stack(int cells) {
  const double t = 1e-4;
  CreasePattern pat = folded_stack_pattern(10, cells, 1e-3, t);
  validate_pattern(pat, "<bench>");
  PatternSheetSpec spec;
  spec.thickness = t;
  spec.valley_law = std::make_shared<LinearCreaseLaw>(1e-3, -0.5 * kPi);
  spec.mountain_law = std::make_shared<LinearCreaseLaw>(1e-3, 0.5 * kPi);
  Model m = build_pattern_model(pat, spec, "<bench>");
  m.contact.enabled = true;
  m.contact.stiffness = 3e7;
  return m;
}

void BM_ContactCandidates(benchmark::State& st) {
  const Model m = folded_stack(static_cast<int>(st.range(0)));
  const State s = initial_state(m);
  BroadPhase broad;
  std::vector<Aabb> boxes;
  std::size_t candidates = 0, overlaps = 0;
  for (auto _ : st) {
    const PairRules rules(m);
    candidates = contact_candidates(m, s, rules, broad, boxes).size();
    benchmark::DoNotOptimize(candidates);
  }
  overlaps = broad.find_pairs(boxes).size();
  st.counters["segments"] = static_cast<double>(m.bodies.size());
  st.counters["box_overlaps"] = static_cast<double>(overlaps);
  st.counters["candidates"] = static_cast<double>(candidates);
  st.SetComplexityN(static_cast<long>(m.bodies.size()));
}
// 10 x 10, 32 x 32, 100 x 100 cells per layer: 1 090, 10 528, 100 900 segments (folds included).
BENCHMARK(BM_ContactCandidates)
    ->Arg(10)
    ->Arg(32)
    ->Arg(100)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oNLogN);

// The rules alone (union-find over the outlines' vertices): part of the above.
void BM_PairRules(benchmark::State& st) {
  const Model m = folded_stack(static_cast<int>(st.range(0)));
  for (auto _ : st) {
    const PairRules rules(m);
    benchmark::DoNotOptimize(&rules);
  }
  st.SetComplexityN(static_cast<long>(m.bodies.size()));
}
BENCHMARK(BM_PairRules)->Arg(10)->Arg(32)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace finseg

BENCHMARK_MAIN();
