// A state of a coarse segmentation carried onto a finer one of the same pattern: how a fold
// made on few segments becomes the start of the fine model's (docs/folding.md, "Folding on a
// coarser segmentation").
#pragma once

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// `fine`'s initial state with every segment moved rigidly with the coarse segment that
/// carries it (of the coarse segments on its face, BodyDef::panel, the one whose flat-sheet
/// outline holds its centre, else the nearest), from where that one starts to where
/// `coarse_state` has it. Each crease's fold-angle history is set to
/// `fraction` x its target (its initial angle where it has none), the branch the fine run's
/// first history commit unwraps the carried angles to (so folds past 180 degrees keep their
/// turns). Throws InputError where a segment has no flat-sheet coordinates or a face no coarse
/// segment.
State refine_state(const Model& coarse, const State& coarse_state, const Model& fine,
                   double fraction);

}  // namespace finseg
