// Two segments joined by a joint and folded onto each other: the stop at a half turn.
#pragma once

#include <vector>

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

class Assembler;

/// Contact of a joint's own two segments (docs/contact.md, "Joints folded flat"). Contact
/// leaves segments that share an edge alone (their corners overlap by construction), so a
/// joint bent past a half turn would let them pass through each other. Past pi (|theta| of a
/// joint's unwrapped rotation, |alpha| of a crease's unwrapped fold angle; ElementHistory), the
/// part of the shorter segment at its centroid's distance r from the joint point has gone
/// delta = (angle - pi) r into the other: the contact law's normal force F(delta) acts there
/// as a couple F r about the joint, the exact gradient of U = int F d(delta). Nothing when
/// contact is disabled.
void add_joint_stops(const Model& model, const State& state, Assembler& as);

/// A joint's stop in action (contact probes): the element, its two bodies, the depth delta
/// (m), the force F(delta) (N) and where it presses, the shorter segment's centroid (m).
struct JointStopReport {
  int element = -1, inner = -1, outer = -1;
  double depth = 0, force = 0;
  Vec3 x_W = Vec3::Zero();
};

/// Every stop in action at `state` (none when contact is disabled).
std::vector<JointStopReport> joint_stop_reports(const Model& model, const State& state);

}  // namespace finseg
