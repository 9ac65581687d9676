// A short rotation step closed onto the mechanism: the static solver's trial where its Newton
// step along a mechanism of stiff joints and soft creases is refused (docs/solvers.md, "Static
// solver").
#pragma once

#include <functional>

#include "elements/assemble.hpp"
#include "model/model.hpp"
#include "model/state.hpp"
#include "solvers/solver.hpp"

namespace finseg {

/// Newton iterations on K + mu diag|K| (mu = kStiffShift) from the current state: the shift
/// holds the soft directions (creases, the sheet's bending: the mechanism) and lets the stiff
/// joints close the gaps a straight step in the rotations opened at second order. Iterates
/// while `residual` falls, until it is below `r_target` or kProjections iterations are done;
/// leaves the forces of the final state in `f`. False where the residual rose or a solve
/// failed (the state is then moved, `f` undefined).
bool project_on_stiff_directions(const Model& model, State& state, BodyForces& f,
                                 SolverStats& stats, double r_target,
                                 const std::function<double(const BodyForces&)>& residual);

/// The shift relative to each diagonal entry of K, and the most iterations (lab cone folds,
/// docs/folding.md: 1e-3 and 5 against 1e-2, 1e-4 and 3).
inline constexpr double kStiffShift = 1e-3;
inline constexpr int kProjections = 5;

}  // namespace finseg
