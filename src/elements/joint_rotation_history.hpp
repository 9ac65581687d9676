// History of joint rotations: each elastic joint's relative rotation, unwrapped through pi.
#pragma once

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// For every joint that resists turning and is not a crease (rotational stiffness, or a side
/// of a plate cell): stores its relative rotation theta = log(R_FE) unwrapped against the
/// last one (ElementHistory::rotation_F), so that a joint bent through a half turn keeps a
/// continuous rotation and energy. Call after each accepted step or equilibrium.
void commit_joint_rotations(const Model& model, State& state);

}  // namespace finseg
