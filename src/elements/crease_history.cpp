#include "elements/crease_history.hpp"

#include "elements/bushing.hpp"

namespace finseg {

void commit_crease_history(const Model& model, State& state) {
  for (size_t k = 0; k < model.elements.size(); ++k) {
    const ElementDef& e = model.elements[k];
    if (e.crease < 0) continue;
    const Mat3 R_WE = state.R_WB[e.inner] * e.R_inner_E;
    const Mat3 R_WF = state.R_WB[e.outer] * e.R_outer_F;
    state.history[k].fold_angle = fold_angle<double>(R_WE, R_WF, state.history[k].fold_angle);
  }
}

}  // namespace finseg
