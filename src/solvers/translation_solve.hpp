// Translations balanced for given rotations: the static solver's correction after each
// rotation step (docs/solvers.md, "Static solver").
#pragma once

#include "elements/assemble.hpp"
#include "model/model.hpp"
#include "model/state.hpp"
#include "solvers/solver.hpp"

namespace finseg {

/// Moves the free bodies' centroids (rotations held) by one Newton step on the translational
/// forces, with the translation block of the stiffness at the current rotations, and leaves
/// the forces of the new state in `f`. With the rotations held, a linear bushing's force is
/// linear in the translations, so for such elements the step balances them exactly. Returns
/// false (state and `f` at the current state) when that block is singular.
bool solve_translations(const Model& model, State& state, BodyForces& f, SolverStats& stats);

}  // namespace finseg
