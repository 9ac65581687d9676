// Contact between segments: entry point used by the force assembly.
#pragma once

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

class Assembler;

/// Adds the normal and friction forces of every active contact (nothing when disabled).
void add_contact_forces(const Model& model, const State& state, Assembler& assembler);

/// Updates contact history (friction anchors) after an accepted step.
void commit_contact_history(const Model& model, State& state);

}  // namespace finseg
