// Forces of the cells' membrane corrections (model/plate_cell_def.hpp, MembraneCellDef;
// docs/stiffness.md, "Cell membrane correction"): each cell's energy 1/2 delta^T Q delta in
// its sides' joint translations, applied as forces at the joints' attachment points.
#pragma once

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

class Assembler;

/// Adds every membrane cell's forces and energy and, when asked, their exact Jacobian blocks.
void add_membrane_cells(const Model& model, const State& state, Assembler& as);

}  // namespace finseg
