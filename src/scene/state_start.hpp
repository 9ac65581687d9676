// A run that starts from a state file (finseg run --state, docs/state-file.md): the model's
// initial configuration becomes that state's, so that "fold once, deploy many times" pulls
// from where the stowed sheet is.
#pragma once

#include "model/model.hpp"
#include "model/state.hpp"
#include "scene/scene_reader.hpp"

namespace finseg {

/// `m` with its initial configuration taken from `s` (a state of `m`): initial poses, each
/// drive's start at its point's position in `s`, each crease's initial fold angle from the
/// history, each chamber's initial volume. Stiffness, laws and rest shapes are unchanged.
Model model_starting_from(const Model& m, const State& s);

/// `start` (a state of `scene.model`) made the start of a fresh run of `scene`, as `finseg run
/// --state` does: time and drive displacements back to 0, no solver memory, and `scene.model`
/// starting from `start` (model_starting_from). Returns the state to run from.
State start_fresh_from(Scene& scene, State start);

}  // namespace finseg
