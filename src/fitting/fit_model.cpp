#include "fitting/fit_model.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.hpp"
#include "core/text.hpp"
#include "model/state.hpp"
#include "probes/recorder.hpp"
#include "scene/scene_reader.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace {

// The recorded force-displacement curve of the fitted drive probe (the first drive probe
// when none is named).
ForceCurve drive_curve(const RunRecorder& rec, const FitCurve& c) {
  for (const ProbeTable& t : rec.tables()) {
    if (t.kind != ProbeKind::Drive || (!c.probe.empty() && t.name != c.probe)) continue;
    const auto column = [&](const std::string& name) {
      return std::find(t.columns.begin(), t.columns.end(), name) - t.columns.begin();
    };
    const auto ix = column("pull_displacement_m"), iy = column("force_N");
    ForceCurve sim;
    sim.source = c.scene;
    for (const auto& row : t.rows) {
      if (!sim.x.empty() && !(row[ix] > sim.x.back())) {
        throw DivergenceError(fmt::format(
            "{}: probe {}: the pull displacement does not increase at {:g} mm; the fit needs a "
            "curve with strictly increasing displacement (a static drive path)",
            c.scene, t.name, 1e3 * row[ix]));
      }
      sim.x.push_back(row[ix]);
      sim.force.push_back(row[iy]);
    }
    // Round-off of the written measured displacements (e.g. the run's own CSV) is no gap.
    const double tol = sim.x.empty() ? 0 : 1e-9 * (sim.x.back() - sim.x.front());
    if (sim.x.size() < 4 || sim.x.front() > c.x.front() + tol || sim.x.back() < c.x.back() - tol) {
      throw DivergenceError(fmt::format(
          "{}: probe {}: the simulated curve ({} points, {:g} .. {:g} mm) does not cover the "
          "measured displacements {:g} .. {:g} mm",
          c.scene, t.name, sim.x.size(), sim.x.empty() ? 0.0 : 1e3 * sim.x.front(),
          sim.x.empty() ? 0.0 : 1e3 * sim.x.back(), 1e3 * c.x.front(), 1e3 * c.x.back()));
    }
    return sim;
  }
  throw InputError(c.scene, "probes",
                   c.probe.empty() ? std::string("the scene has no drive probe to fit")
                                   : fmt::format("no drive probe named '{}'", c.probe));
}

}  // namespace

FitModel::FitModel(const FitSpec& spec) : spec_(spec) {
  for (const FitCurve& c : spec.curves) scene_text_.push_back(read_text_file(c.scene));
}

std::vector<std::vector<double>> FitModel::simulate(const std::vector<double>& values) const {
  std::vector<std::vector<double>> forces;
  for (std::size_t k = 0; k < spec_.curves.size(); ++k) {
    const FitCurve& c = spec_.curves[k];
    std::vector<Override> overrides = c.set;
    for (std::size_t i = 0; i < values.size(); ++i) {
      for (const std::string& path : spec_.parameters[i].paths) {
        overrides.push_back({path, fmt::format("{:.17g}", values[i])});
      }
    }
    const Scene scene = parse_scene(scene_text_[k], c.scene, overrides);
    RunRecorder rec(scene.model, scene.solver, {});
    State state = initial_state(scene.model);
    ++simulations_;
    const SolverStats stats =
        run_solver(scene.model, state, scene.solver,
                   [&](const State& s, const BodyForces& f) { rec.record(s, f); });
    if (stats.status != "ok") {
      throw DivergenceError(fmt::format("{}: the simulation diverged: {}", c.scene, stats.message));
    }
    forces.push_back(resample_curve(drive_curve(rec, c), c.x));
  }
  return forces;
}

}  // namespace finseg
