// Cost of reading, validating and writing FOLD crease patterns against their size: an
// n x n grid (2 n (n + 1) edges). validate_pattern and the crossing search should grow
// about linearly (grid sort: n log n).
#include <benchmark/benchmark.h>

#include "patterns/fold_format.hpp"
#include "patterns/grid_pattern.hpp"
#include "patterns/pattern_checks.hpp"

namespace finseg {
namespace {

CreasePattern grid(const benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  return grid_crease_pattern(n, n, 1e-3, 1e-3);
}

void BM_ValidatePattern(benchmark::State& st) {
  CreasePattern p = grid(st);
  for (auto _ : st) validate_pattern(p, "<bench>");
  st.counters["edges"] = static_cast<double>(p.edges.size());
  st.SetComplexityN(static_cast<long>(p.edges.size()));
}

void BM_FindEdgeCrossing(benchmark::State& st) {
  const CreasePattern p = grid(st);
  for (auto _ : st) {
    benchmark::DoNotOptimize(find_edge_crossing(p.vertices_flat_m, p.edges, 1e-12));
  }
  st.counters["edges"] = static_cast<double>(p.edges.size());
  st.SetComplexityN(static_cast<long>(p.edges.size()));
}

// Parse and validate FOLD text (JSON parse included).
void BM_ParseFold(benchmark::State& st) {
  const std::string text = fold_text(grid(st));
  for (auto _ : st) benchmark::DoNotOptimize(parse_fold(text, "<bench>"));
  st.counters["MB"] = static_cast<double>(text.size()) / 1e6;
  st.SetComplexityN(static_cast<long>(text.size()));
}

void BM_FoldText(benchmark::State& st) {
  const CreasePattern p = grid(st);
  for (auto _ : st) benchmark::DoNotOptimize(fold_text(p));
  st.SetComplexityN(static_cast<long>(p.edges.size()));
}

BENCHMARK(BM_ValidatePattern)
    ->RangeMultiplier(2)
    ->Range(32, 512)
    ->Complexity()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FindEdgeCrossing)
    ->RangeMultiplier(2)
    ->Range(32, 512)
    ->Complexity()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseFold)
    ->RangeMultiplier(4)
    ->Range(32, 512)
    ->Complexity()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FoldText)
    ->RangeMultiplier(4)
    ->Range(32, 512)
    ->Complexity()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace finseg

BENCHMARK_MAIN();
