// finseg run SCENE --out DIR [--quiet]: runs a scene and writes its probes' CSV files,
// optional VTK / HTML / plots and DIR/summary.json (docs/scene.md, "Run outputs").
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>

#include "apps/finseg/commands.hpp"
#include "apps/finseg/progress.hpp"
#include "probes/recorder.hpp"
#include "scene/scene_reader.hpp"
#include "writers/run_outputs.hpp"

namespace finseg::cli {

namespace {

struct RunOptions {
  std::string scene, out;
  bool quiet = false;
};

std::string where(const RunRecorder& rec) {
  const double x = rec.last_abscissa();
  if (rec.abscissa() == "t_s") return fmt::format("t = {:.4g} s", x);
  if (rec.abscissa() == "pull_displacement_m") return fmt::format("pull {:.4g} mm", 1e3 * x);
  return fmt::format("load {:.3g}", x);
}

void print_results(const RunRecorder& rec, const RunOptions& o, const SolverStats& stats,
                   double wall, const Model& model) {
  fmt::print("finseg run {}: {} outputs, {} steps, wall {:.3g} s -> {}\n", o.scene, rec.outputs(),
             stats.steps, wall, o.out);
  for (const ProbeTable& t : rec.tables()) {
    if (t.rows.empty()) continue;
    const auto& r = t.rows.back();
    if (t.kind == ProbeKind::Point) {
      fmt::print("  {}: final [{:.6g}, {:.6g}, {:.6g}] m\n", t.name, r[1], r[2], r[3]);
    } else if (t.kind == ProbeKind::Drive) {
      const nlohmann::json s = probe_summary(t, deployed_at_of(model, t));
      fmt::print("  {}: {}; largest force {:.6g} N at pull {:.6g} mm\n", t.name,
                 s["deployment_peak_force_N"].is_null()
                     ? std::string("no deployment peak")
                     : fmt::format("deployment peak {:.6g} N at pull {:.6g} mm",
                                   s["deployment_peak_force_N"].get<double>(),
                                   1e3 * s["deployment_peak_displacement_m"].get<double>()),
                 s["peak_force_N"].get<double>(), 1e3 * s["peak_displacement_m"].get<double>());
    }
  }
}

void run_scene(const RunOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const Scene scene = read_scene(o.scene);
  // A summary.json from an earlier run must not make this one look complete.
  std::filesystem::remove(std::filesystem::path(o.out) / "summary.json");
  RecorderOptions ro;
  ro.frames = scene.outputs.vtk || scene.outputs.html;
  ro.phases = scene.outputs.phases.enabled;
  for (int p : scene.outputs.phases.panels) ro.watched_panels.push_back(p - 1);
  RunRecorder rec(scene.model, scene.solver, ro);
  State state = initial_state(scene.model);
  ProgressLine progress(!o.quiet && stderr_is_terminal(), [&] { return where(rec); });
  const SolverStats stats = run_solver(
      scene.model, state, scene.solver,
      [&](const State& s, const BodyForces& f) { rec.record(s, f); },
      [&](double fraction) { progress.update(fraction); });
  progress.finish();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const RunReport report = write_run_outputs(o.out, scene, rec, stats, wall);
  for (const std::string& w : report.warnings) fmt::print(stderr, "finseg: warning: {}\n", w);
  if (stats.status != "ok") {
    fmt::print(stderr, "finseg: error: {}: the simulation diverged: {}\n", o.scene, stats.message);
    fmt::print(stderr, "finseg: kept the {} outputs recorded before ({} to {})\n", rec.outputs(),
               where(rec), o.out);
    throw ExitStatus{3};
  }
  if (!o.quiet) print_results(rec, o, stats, wall, scene.model);
}

}  // namespace

void register_run(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* run = app.add_subcommand("run", "run a scene file; write probe CSVs and summary.json");
  run->add_option("SCENE", o->scene, "scene file (YAML, docs/scene.md)")->required();
  run->add_option("--out", o->out, "output folder (created if needed)")->required();
  run->add_flag("--quiet", o->quiet, "no progress display and no result lines");
  run->callback([o] { run_scene(*o); });
}

}  // namespace finseg::cli
