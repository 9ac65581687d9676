// A state of a coarse segmentation carried onto a finer one of the same pattern: how a fold
// made on few segments becomes the start of the fine model's (docs/folding.md, "Folding on a
// coarser segmentation").
#pragma once

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// The coarse body that carries fine body `b`: of the coarse bodies on the same pattern face
/// (BodyDef::panel), the one whose material outline holds b's centre, else the nearest.
/// Throws InputError where a body has no material coordinates or its face has no coarse body.
int carrying_body(const Model& coarse, const BodyDef& b);

/// `fine`'s initial state with every body moved rigidly with its carrying body from where
/// that body starts to where `coarse_state` has it. Each crease's fold-angle history is set to
/// `fraction` x its target (its initial angle where it has none), the branch the fine run's
/// first history commit unwraps the carried angles to (so folds past 180 degrees keep their
/// turns).
State refine_state(const Model& coarse, const State& coarse_state, const Model& fine,
                   double fraction);

}  // namespace finseg
