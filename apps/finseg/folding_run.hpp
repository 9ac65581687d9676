// `finseg run --fold` (docs/folding.md): the scene's folding run in place of its run, made on
// a coarser cut of the pattern first where the scene asks for it.
#pragma once

#include <optional>

#include "model/state.hpp"
#include "scene/scene_reader.hpp"
#include "writers/run_outputs.hpp"

namespace finseg::cli {

/// Where a folding run starts: the coarse cut's fold carried over (nothing: the scene's
/// initial state), and that fold's counts for summary.json.
struct FoldingStart {
  std::optional<State> state;
  std::vector<RunStage> stages;
};

/// Makes `scene` its folding run: crease rest angles carried to their targets, the folding
/// solver. With folding.coarse_subdivisions the fold is first solved on that cut of the
/// pattern (a progress line unless `quiet`) and the fine run starts from its stowed poses in
/// one load increment; `resume`: the run continues from its checkpoint, so the coarse fold is
/// not solved (the settings are still the carried run's).
FoldingStart make_folding_run(Scene& scene, bool quiet, bool resume);

}  // namespace finseg::cli
