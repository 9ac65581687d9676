// Per-segment loads for the VTK frames: resultants, the force elements' largest loads,
// bordering creases and contact forces.
#pragma once

#include "collision/contact_forces.hpp"
#include "elements/assemble.hpp"
#include "writers/frames.hpp"

namespace finseg {

/// Fills every field of SegmentFields at `state` (forces: compute_forces at that state).
/// A segment that borders two creases shows the one of the first such element.
SegmentFields segment_fields(const Model& model, const State& state, const BodyForces& forces,
                             const ContactSummary& contact);

}  // namespace finseg
