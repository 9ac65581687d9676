#include "scene/folding_run.hpp"

#include <fmt/format.h>

#include <chrono>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "generators/folding.hpp"
#include "generators/state_refinement.hpp"

namespace finseg {

namespace {

// The static solver's rest angles reach their targets at load 1; a dynamic one's at the
// folding's duration.
double ramp_of(const Scene& scene) {
  return scene.folding_solver.kind == SolverKind::Static ? 1.0 : scene.folding->duration;
}

// The fold solved on the pattern cut into `coarse_subdivisions` (the same scene text and
// overrides otherwise), carried onto `scene`'s segments.
FoldingStart fold_on_coarse_cut(const Scene& scene, const std::string& yaml,
                                const CoarseFoldProgress& progress) {
  const int n = scene.folding->coarse_subdivisions;
  std::vector<Override> overrides = scene.overrides;
  overrides.push_back({"pattern.subdivisions", std::to_string(n)});
  overrides.push_back({"folding.coarse_subdivisions", "0"});
  Scene coarse = parse_scene(yaml, scene.file, overrides);
  const double fraction = scene.folding->fraction;
  coarse.model = folding_model(coarse.model, initial_state(coarse.model), fraction, ramp_of(scene));
  State state = initial_state(coarse.model);
  const std::size_t segments = coarse.model.bodies.size();
  const auto start = std::chrono::steady_clock::now();
  const SolverStats stats = run_solver(
      coarse.model, state, scene.folding_solver, [](const State&, const BodyForces&) {},
      [&](const SolverProgress& p) {
        if (progress) progress(segments, n, p.fraction);
      });
  if (stats.status != "ok") {
    throw DivergenceError(
        fmt::format("the fold on the coarse cut (pattern.subdivisions {}): {}", n, stats.message));
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const RunStage stage{fmt::format("fold on the coarse cut (pattern.subdivisions {})", n), segments,
                       stats, wall};
  return {refine_state(coarse.model, state, scene.model, fraction), {stage}};
}

}  // namespace

FoldingStart make_folding_run(Scene& scene, const std::string& yaml, bool resume, bool from_state,
                              const CoarseFoldProgress& progress) {
  if (!scene.folding) {
    throw InputError(scene.file, "folding", "--fold needs a folding: section (docs/folding.md)");
  }
  const bool carried = scene.folding->coarse_subdivisions > 0;
  if (carried && from_state) {
    throw InputError(scene.file, "folding.coarse_subdivisions",
                     "not from a start state (--state): the coarse cut folds from the scene's "
                     "start");
  }
  FoldingStart start;
  if (carried && !resume) start = fold_on_coarse_cut(scene, yaml, progress);
  scene.model = folding_model(scene.model, initial_state(scene.model), scene.folding->fraction,
                              ramp_of(scene));
  scene.solver = scene.folding_solver;
  // The carried poses are the fold's end: the fine model's equilibrium there, in one increment.
  if (carried) scene.solver.load_steps = 1;
  return start;
}

}  // namespace finseg
