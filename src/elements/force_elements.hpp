// The force elements' share of compute_forces: wrenches, energy and (closed-form or
// automatic) Jacobian blocks of every bushing and crease, evaluated in parallel (OpenMP)
// when the model is large enough. Deterministic for any thread count: each element writes
// its own slots and the sums run in element order afterwards.
#pragma once

#include "elements/assembler.hpp"

namespace finseg {

/// Adds every force element of the model to `as`.
void add_force_elements(const Model& model, const State& state, Assembler& as);

}  // namespace finseg
