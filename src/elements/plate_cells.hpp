// Forces of the plate cells' curvature corrections (model/plate_cell_def.hpp,
// docs/stiffness.md): each cell's energy 1/2 Theta^T Q Theta in its sides' relative
// rotations, applied as couples on the sides' two bodies.
#pragma once

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

class Assembler;

/// Adds every plate cell's couples and energy; with the Jacobian, its rotational blocks for
/// small relative rotations (the rotation of the cell frame itself is not differentiated).
void add_plate_cells(const Model& model, const State& state, Assembler& as);

}  // namespace finseg
