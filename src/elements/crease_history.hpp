// History of creases: unwrapped fold angle and opening count, updated after accepted steps.
#pragma once

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// Stores each crease's current unwrapped fold angle and counts completed openings.
void commit_crease_history(const Model& model, State& state);

}  // namespace finseg
