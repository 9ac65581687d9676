// finseg modes SCENE [--count N] [--out FILE.csv]: natural frequencies (Hz) of small
// vibrations about the static equilibrium under the scene's loads and gravity (drives held
// at their start).
#include <fmt/format.h>

#include <memory>
#include <string>

#include "apps/finseg/commands.hpp"
#include "core/error.hpp"
#include "scene/scene_reader.hpp"
#include "writers/atomic_write.hpp"

namespace finseg::cli {

namespace {

struct ModesOptions {
  std::string scene, out;
  int count = 6;
};

void modes(const ModesOptions& o) {
  Scene scene = read_scene(o.scene);
  Model& m = scene.model;
  for (DriveDef& d : m.drives) d.travel = 0;  // equilibrium at the start of the pull
  SolverSettings settings = scene.solver;
  settings.kind = SolverKind::Static;
  State state = initial_state(m);
  const SolverStats stats = run_solver(m, state, settings, {});
  if (stats.status != "ok") {
    fmt::print(stderr, "finseg: error: {}: no static equilibrium: {}\n", o.scene, stats.message);
    throw ExitStatus{3};
  }
  const std::vector<double> hz = natural_frequencies(m, state, o.count);
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
}

}  // namespace

void register_modes(CLI::App& app) {
  auto o = std::make_shared<ModesOptions>();
  CLI::App* cmd =
      app.add_subcommand("modes", "natural frequencies (Hz) about the static equilibrium");
  cmd->add_option("SCENE", o->scene, "scene file")->required();
  cmd->add_option("--count", o->count, "number of modes")->check(CLI::Range(1, 100000));
  cmd->add_option("--out", o->out, "also write mode,frequency_Hz as CSV");
  cmd->callback([o] { modes(*o); });
}

}  // namespace finseg::cli
