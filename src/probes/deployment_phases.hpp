// Deployment phases of a pull-open test (paper section 4.2, Fig. 20): initial deformation,
// contact/collision, bending of the panels next to the clamped ones. docs/zigzag.md states
// the detection rule.
#pragma once

#include <vector>

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// Total bend of one panel (0-based): the sum of |rotation about the crease-parallel axis|
/// over its bending joints (creases excluded), rad.
double panel_bend_angle(const Model& model, const State& state, int panel);

/// Largest panel_bend_angle over the watched panels (0-based), rad.
double watched_bend(const Model& model, const State& state, const std::vector<int>& panels);

/// What the phase detector needs at each recorded equilibrium.
struct PhaseSample {
  double displacement = 0;  ///< pull displacement, m
  int active_contacts = 0;
  double bend = 0;  ///< largest panel_bend_angle of the watched panels, rad
};

/// Start of each phase as a pull displacement (m); NaN where a phase never began.
struct DeploymentPhases {
  double initial_deformation = 0;
  double contact = 0;
  double bending = 0;
};

/// Default bend of a watched panel that marks the bending phase: 0.1 rad (5.7 deg), rad.
constexpr double kDefaultBendThreshold = 0.1;

/// Rule: contact begins at the first sample with an active contact; bending begins at the
/// first later sample whose watched-panel bend exceeds `bend_threshold` (rad).
DeploymentPhases detect_phases(const std::vector<PhaseSample>& samples, double bend_threshold);

}  // namespace finseg
