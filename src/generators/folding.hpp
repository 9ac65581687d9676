// Folding by simulation (docs/folding.md): the stowed state made from the flat (or partly
// folded) sheet by carrying every crease's rest angle to its target fold angle while the
// solver follows, contact on, so that layers cannot pass through each other.
#pragma once

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// How far and how fast the creases are folded.
struct FoldingSpec {
  double fraction = 1.0;  ///< share of each crease's target angle folded to, (0, 1]
  double duration = 1.0;  ///< s over which the rest angles move (dynamic solvers), > 0
  /// Fold a coarser segmentation of the same pattern (its pattern.subdivisions) first and
  /// carry its stowed poses onto this one (generators/state_refinement.hpp); 0: fold this one.
  int coarse_subdivisions = 0;
};

/// The model of the folding run: every crease with a target fold angle gets its law moved
/// along its angle so that it rests where the crease is at t = 0 and at `fraction` x its
/// target from t = `ramp` on (the law's shape about its rest is kept); drives go slack (no
/// gauge stiffness, no travel) so that nothing holds the sheet where it started. Bodies,
/// elements and drives keep their number and order: a state of this model is a state of `m`.
/// `start` (a state of `m`) is where the folding starts (its crease fold angles).
Model folding_model(const Model& m, const State& start, double fraction, double ramp);

}  // namespace finseg
