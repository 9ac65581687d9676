// `finseg run --fold` and Scene.run(fold=True) (docs/folding.md): the scene's folding run in
// place of its run, made on a coarser cut of the pattern first where the scene asks for it.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/state.hpp"
#include "scene/scene_reader.hpp"
#include "solvers/run_stage.hpp"

namespace finseg {

/// Where a folding run starts: the coarse cut's fold carried over (nothing: the scene's
/// initial state), and that fold's counts for summary.json.
struct FoldingStart {
  std::optional<State> state;
  std::vector<RunStage> stages;
};

/// Progress of the fold on the coarse cut: its segments, its pattern.subdivisions and the
/// fraction of its load path done.
using CoarseFoldProgress =
    std::function<void(std::size_t segments, int subdivisions, double fraction)>;

/// Appended to the scene's text for the inputs hash of a folding run's checkpoint: it is not
/// the scene's own run's (scene_inputs_hash).
inline constexpr const char* kFoldingRunMark = "\n# finseg run --fold";

/// Makes `scene` (read from `yaml`, its overrides in `scene.overrides`) its folding run: crease
/// rest angles carried to their targets, the folding solver. With folding.coarse_subdivisions
/// the fold is first solved on that cut of the pattern (`progress` told as it goes) and the
/// fine run starts from its stowed poses in one load increment; `resume`: the run continues
/// from its checkpoint, so the coarse fold is not solved (the settings are still the carried
/// run's). `from_state`: `scene` starts from a state (--state), which a coarse cut cannot
/// (InputError). Throws InputError without a folding: section, DivergenceError when the
/// coarse fold fails.
FoldingStart make_folding_run(Scene& scene, const std::string& yaml, bool resume, bool from_state,
                              const CoarseFoldProgress& progress = {});

}  // namespace finseg
