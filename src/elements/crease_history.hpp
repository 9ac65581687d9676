// History of creases: unwrapped fold angle and opening count, updated after accepted steps.
#pragma once

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// For every crease element: stores the current fold angle unwrapped against the previous
/// one (ElementHistory::fold_angle, continuous through +-pi and over several turns), and
/// counts openings: `opened` is set when the opening angle pi - s alpha rises above the
/// law's OpeningRule::opened_above; when it then falls below closed_below, `opened` is
/// cleared and `openings` rises by one. Call after each accepted step or equilibrium.
void commit_crease_history(const Model& model, State& state);

}  // namespace finseg
