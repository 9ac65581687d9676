// Table of the paper's pull test: each Table 1 condition at several discretisations.
// Plain main (not Google Benchmark): condition, segments/panel, equilibria, Newton
// iterations, wall time, peak force. BENCHMARKS.md, "Folded strip", records its output.
// Arguments: [condition [segments [crease_refinement [contact [path]]]]], path `strip` (the
// generator, default) or `pattern` (the strip's FOLD pattern through the pattern path,
// docs/zigzag.md).
#include <fmt/format.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "generators/zigzag_conditions.hpp"
#include "patterns/zigzag_pattern.hpp"
#include "probes/pull_test.hpp"

int main(int argc, char** argv) {
  using namespace finseg;
  std::vector<int> conditions{1, 2, 3, 4}, segments{4, 8, 16};
  if (argc > 1) conditions = {std::atoi(argv[1])};
  if (argc > 2) segments = {std::atoi(argv[2])};
  // deploy_peak: the deployment peak (docs/zigzag.md); largest: the largest force of the travel.
  fmt::print(
      "{:>9} {:>14} {:>8} {:>10} {:>9} {:>8} {:>11} {:>13} {:>10} {:>11} {:>10} {:>10} "
      "{:>10}\n",
      "condition", "", "segs", "equilibria", "newton", "settles", "wall_s", "deploy_peak_N",
      "at_mm", "largest_N", "at_mm", "contact_mm", "bending_mm");
  for (int c : conditions) {
    for (int n : segments) {
      ZigzagSpec spec = paper_condition(c);
      spec.segments_per_panel = n;
      if (argc > 3) spec.crease_refinement = std::atof(argv[3]);
      if (argc > 4) spec.contact = std::atoi(argv[4]) != 0;
      const bool pattern = argc > 5 && std::string(argv[5]) == "pattern";
      const Model m = pattern ? build_zigzag_pattern_model(spec) : build_zigzag_model(spec);
      const PullResult r = run_pull_test(m, {1, 4}, kDefaultBendThreshold);
      fmt::print(
          "{:>9} {:>14} {:>8} {:>10} {:>9} {:>8} {:>11.3f} {:>13.4f} {:>10.1f} {:>11.4f} {:>10.1f} "
          "{:>10.1f} {:>10.1f} {}\n",
          c, paper_condition_label(c), n, r.stats.steps, r.stats.newton_iterations, r.stats.settles,
          r.stats.wall_seconds, r.deployment_peak.force, 1e3 * r.deployment_peak.x, r.peak_force,
          1e3 * r.peak_displacement, 1e3 * r.phases.contact, 1e3 * r.phases.bending,
          r.stats.status);
      if (r.stats.status != "ok") fmt::print("  {}\n", r.stats.message);
      if (getenv("FINSEG_CURVE")) {
        for (const PullSample& p : r.samples) {
          fmt::print("  {:8.2f} {:9.5f} {:4d} {:9.3g} {:7.4f}\n", 1e3 * p.displacement, p.force,
                     p.active_contacts, p.max_penetration, p.bend);
        }
      }
    }
  }
  return 0;
}
