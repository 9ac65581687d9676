// `finseg run --fold` (docs/folding.md): the scene's folding run in place of its run, made on
// a coarser cut of the pattern first where the scene asks for it.
#pragma once

#include <optional>

#include "model/state.hpp"
#include "scene/scene_reader.hpp"

namespace finseg::cli {

/// Makes `scene` its folding run: crease rest angles carried to their targets, the folding
/// solver. With folding.coarse_subdivisions the fold is first solved on that cut of the
/// pattern (a progress line unless `quiet`) and the fine run starts from its stowed poses in
/// one load increment; returned: that start (nothing: the scene's initial state).
std::optional<State> make_folding_run(Scene& scene, bool quiet);

}  // namespace finseg::cli
