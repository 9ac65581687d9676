// What one force element carries at a state: its force and moment in its own frame, and
// for a crease the fold angle and the law's moment. Used by the probes and the VTK frames.
#pragma once

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// Load of force element k at a state (elements/bushing.hpp: element_kernel).
struct ElementLoad {
  Vec3 force_F = Vec3::Zero();   ///< force on the inner body at P+, element frame F, N
  Vec3 moment_F = Vec3::Zero();  ///< moment on the inner body about P+, frame F, N m
  bool crease = false;           ///< the element is a crease (the fields below are set)
  double fold_angle = 0;         ///< signed fold angle alpha of E relative to F about y, rad
  double opening_angle = 0;      ///< theta = pi - s alpha (0 shut, pi flat), rad
  double crease_moment = 0;      ///< M_alpha = dU/dalpha from the crease law, N m
};

/// Evaluates force element k at `state` (springs, dampers and crease law together).
ElementLoad element_load(const Model& model, const State& state, int k);

/// Indices of the force elements of crease c, in element order.
std::vector<int> crease_elements(const Model& model, int c);

}  // namespace finseg
