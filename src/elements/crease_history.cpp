#include "elements/crease_history.hpp"

#include "elements/bushing.hpp"

namespace finseg {

void commit_crease_history(const Model& model, State& state) {
  for (size_t k = 0; k < model.elements.size(); ++k) {
    const ElementDef& e = model.elements[k];
    if (e.crease < 0) continue;
    ElementHistory& h = state.history[k];
    const Mat3 R_WE = state.R_WB[e.inner] * e.R_inner_E;
    const Mat3 R_WF = state.R_WB[e.outer] * e.R_outer_F;
    h.fold_angle = fold_angle<double>(R_WE, R_WF, h.fold_angle);
    const CreaseDef& crease = model.creases[static_cast<size_t>(e.crease)];
    if (!crease.law) continue;
    // Opening count: opened once the opening angle passes `opened_above`; the opening is
    // complete when it falls below `closed_below` again (hysteresis between the two).
    const OpeningRule rule = crease.law->opening_rule();
    const double theta = opening_angle(crease_direction(crease) * h.fold_angle);
    if (!h.opened && theta > rule.opened_above) {
      h.opened = true;
    } else if (h.opened && theta < rule.closed_below) {
      h.opened = false;
      ++h.openings;
    }
  }
}

}  // namespace finseg
