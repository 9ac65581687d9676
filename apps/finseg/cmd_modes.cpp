// finseg modes SCENE [--count N] [--out FILE.csv] [--vtk DIR]: natural frequencies (Hz) of
// small vibrations about the static equilibrium under the scene's loads and gravity (drives
// held at their start), and optionally the mode shapes as VTK (docs/vtk.md).
#include <fmt/format.h>

#include <chrono>
#include <memory>
#include <string>

#include "apps/finseg/commands.hpp"
#include "apps/finseg/progress.hpp"
#include "core/error.hpp"
#include "scene/scene_reader.hpp"
#include "solvers/modes.hpp"
#include "writers/atomic_write.hpp"
#include "writers/vtk.hpp"

namespace finseg::cli {

namespace {

struct ModesOptions {
  std::string scene, out, vtk;
  int count = 6;
  bool quiet = false;
  double progress_every = 5;  // wall s between progress lines when stderr is not a terminal
};

// The eigen solve is one library call without a fraction to report: its start and end are
// printed, so that a long solve is not silence.
void say(const ModesOptions& o, const std::string& what) {
  if (!o.quiet) fmt::print(stderr, "finseg: {}\n", what);
}

void modes(const ModesOptions& o) {
  Scene scene = read_scene(o.scene);
  Model& m = scene.model;
  for (DriveDef& d : m.drives) d.travel = 0;  // equilibrium at the start of the pull
  SolverSettings settings = scene.solver;
  settings.kind = SolverKind::Static;
  State state = initial_state(m);
  ProgressLine progress(
      progress_mode(o.quiet),
      [&] { return fmt::format("static equilibrium, load {:.3g}", state.t); }, o.progress_every);
  const SolverStats stats = run_solver(
      m, state, settings, {}, [&](const SolverProgress& p) { progress.update(p.fraction); });
  progress.finish();
  if (stats.status != "ok") {
    fmt::print(stderr, "finseg: error: {}: no static equilibrium: {}\n", o.scene, stats.message);
    throw ExitStatus{3};
  }
  std::vector<double> hz;
  std::vector<ModeShape> shapes;
  const auto start = std::chrono::steady_clock::now();
  say(o, fmt::format("eigen solve: {} modes of {} degrees of freedom ...", o.count, m.num_dofs));
  if (o.vtk.empty()) {
    hz = natural_frequencies(m, state, o.count);
  } else {
    for (const Mode& mode : natural_modes(m, state, o.count)) {
      hz.push_back(mode.frequency_hz);
      shapes.push_back(mode_shape(m, state, mode));
    }
  }
  say(o,
      fmt::format("eigen solve done in {:.2f} s",
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()));
  std::string csv = "mode,frequency_Hz\n";
  fmt::print("{:>5} {:>16}\n", "mode", "frequency_Hz");
  for (std::size_t i = 0; i < hz.size(); ++i) {
    fmt::print("{:>5} {:>16.8g}\n", i + 1, hz[i]);
    csv += fmt::format("{},{:.12g}\n", i + 1, hz[i]);
  }
  if (!o.out.empty()) {
    write_file_atomically(o.out, csv);
    fmt::print("wrote {}\n", o.out);
  }
  if (!o.vtk.empty()) {
    write_vtk_modes(o.vtk, "modes", m, Frame{0, state.p_W, state.R_WB, {}, {}, {}, {}, {}, {}, {}},
                    shapes);
    fmt::print("wrote {}/modes.pvd ({} mode shapes)\n", o.vtk, shapes.size());
  }
}

}  // namespace

void register_modes(CLI::App& app) {
  auto o = std::make_shared<ModesOptions>();
  CLI::App* cmd =
      app.add_subcommand("modes", "natural frequencies (Hz) about the static equilibrium");
  cmd->add_option("SCENE", o->scene, "scene file")->required();
  cmd->add_option("--count", o->count, "number of modes")->check(CLI::Range(1, 100000));
  cmd->add_option("--out", o->out, "also write mode,frequency_Hz as CSV");
  cmd->add_option("--vtk", o->vtk, "also write the mode shapes as DIR/modes.pvd + .vtu");
  cmd->add_flag("--quiet", o->quiet, "no progress on stderr");
  cmd->add_option("--progress-every", o->progress_every,
                  "wall seconds between progress lines when stderr is not a terminal")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->callback([o] { modes(*o); });
}

}  // namespace finseg::cli
