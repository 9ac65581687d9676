// The gauge spring of a drive (paper: the force gauge between the slide and the sheet): a
// spring and damper (isotropic, or softer across its direction: a string, which may also be
// pull-only and go slack) from a body point to the drive's moving target, with its closed-form
// Jacobian (docs/solvers.md, "Closed-form Jacobians").
#pragma once

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

class Assembler;

/// Adds every drive's gauge force, energy and (when asked) Jacobian: closed form, or the
/// automatic differentiation of the same kernel when ForceJacobian::autodiff (the oracle).
void add_drive_gauges(const Model& model, const State& state, Assembler& as);

/// Gauge force of drive d: force the gauge spring applies to the structure, world frame, N.
Vec3 drive_force(const Model& model, const State& state, int d);

}  // namespace finseg
