// finseg compare SIM.csv EXP1.csv [EXP2.csv ...]: simulation against repeated measurements
// (paper Fig. 23). docs/compare.md describes the files and the numbers.
#include <fmt/format.h>

#include <string>
#include <vector>

#include "apps/finseg/commands.hpp"
#include "comparison/compare.hpp"
#include "core/error.hpp"

namespace finseg::cli {

namespace {

struct CompareOptions {
  std::string sim, out = "comparison";
  std::vector<std::string> experiments, sim_columns, exp_columns;
  std::vector<double> window_mm;
  int samples = 201;
  bool no_plot = false;
};

std::pair<std::string, std::string> columns(const std::vector<std::string>& v) {
  return v.empty() ? std::pair<std::string, std::string>{} : std::pair{v[0], v[1]};
}

void run_compare(const CompareOptions& o) {
  const auto [sx, sy] = columns(o.sim_columns);
  const auto [ex, ey] = columns(o.exp_columns);
  const ForceCurve sim = read_force_curve(o.sim, sx, sy);
  std::vector<ForceCurve> runs;
  for (const std::string& e : o.experiments) runs.push_back(read_force_curve(e, ex, ey));
  CompareWindow window;
  if (!o.window_mm.empty()) {
    if (!(o.window_mm[1] > o.window_mm[0])) {
      throw InputError(
          "<cli>", "--window",
          fmt::format("{:g},{:g}; MIN_MM must be below MAX_MM", o.window_mm[0], o.window_mm[1]));
    }
    window = {1e-3 * o.window_mm[0], 1e-3 * o.window_mm[1]};
  }
  const auto print_notes = [](const ForceCurve& f) {
    for (const std::string& n : f.notes) fmt::print(stderr, "finseg: note: {}: {}\n", f.source, n);
  };
  print_notes(sim);
  for (const ForceCurve& f : runs) print_notes(f);
  const Comparison c = compare_curves(sim, runs, o.samples, window);
  write_comparison(c, sim, runs, o.out, !o.no_plot);
  fmt::print("common range {:.3f} .. {:.3f} mm, {} measurements\n", 1e3 * c.x.front(),
             1e3 * c.x.back(), runs.size());
  fmt::print(
      "{}: simulation {:.5g} N at {:.2f} mm, measured mean {:.5g} N at {:.2f} mm\n",
      c.peak_rule == "deployment" ? "deployment peak" : "peak force (largest; no deployment peak)",
      c.sim_peak, 1e3 * c.sim_peak_x, c.mean_peak, 1e3 * c.mean_peak_x);
  fmt::print(
      "largest force: simulation {:.5g} N at {:.2f} mm, measured mean {:.5g} N at {:.2f} mm\n",
      c.sim_max, 1e3 * c.sim_max_x, c.mean_max, 1e3 * c.mean_max_x);
  fmt::print("error at peak force {:+.3f} %, rms error {:.4g} N, max error {:.4g} N at {:.2f} mm\n",
             100 * c.peak_error, c.rms_error, c.max_error, 1e3 * c.max_error_x);
  fmt::print("wrote {}/comparison.csv, comparison.json{}\n", o.out,
             o.no_plot ? "" : ", comparison.png");
}

}  // namespace

void register_compare(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* c = app.add_subcommand(
      "compare", "compare a simulated pull curve with measured ones (peak error, rms, plot)");
  c->add_option("sim", o->sim, "simulation CSV (e.g. the gauge probe: pull_displacement_m,force_N)")
      ->required();
  c->add_option("experiments", o->experiments, "measured CSV files (pull_displacement_mm,force_N)")
      ->required();
  c->add_option("--out", o->out, "output directory")->capture_default_str();
  c->add_option("--sim-columns", o->sim_columns,
                "displacement and force column names of the simulation file")
      ->expected(2)
      ->delimiter(',');
  c->add_option("--exp-columns", o->exp_columns,
                "displacement and force column names of the measured files")
      ->expected(2)
      ->delimiter(',');
  c->add_option("--samples", o->samples, "points of the common displacement grid")
      ->check(CLI::Range(2, 1000000))
      ->capture_default_str();
  c->add_option("--window", o->window_mm,
                "MIN_MM,MAX_MM: compare (and seek the peaks) only in this displacement window, mm")
      ->expected(2)
      ->delimiter(',');
  c->add_flag("--no-plot", o->no_plot, "skip comparison.png (no gnuplot needed)");
  c->callback([o] { run_compare(*o); });
}

}  // namespace finseg::cli
