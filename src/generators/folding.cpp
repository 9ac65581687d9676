#include "generators/folding.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "elements/crease_law.hpp"
#include "elements/crease_laws/shifted.hpp"

namespace finseg {

Model folding_model(const Model& m, const State& start, double fraction, double ramp) {
  Model out = m;
  for (std::size_t e = 0; e < out.elements.size(); ++e) {
    const int c = out.elements[e].crease;
    if (c < 0) continue;
    CreaseDef& crease = out.creases[c];
    if (crease.target_fold_angle == 0 || !crease.law) continue;
    // Rest angles in the law's own angle: the fold angle at t = 0, then the target's share.
    const double s = law_direction(crease);
    const double from = s * start.history[e].fold_angle,
                 to = s * fraction * crease.target_fold_angle;
    crease.law = std::make_shared<ShiftedCreaseLaw>(crease.law, from, to, ramp);
    // The solver's force scale: the crease's moment at its start once fully driven, over the
    // sheet's length.
    const double moment = crease.law->evaluate(from, ElementHistory{}, ramp).moment;
    out.actuation_force = std::max(
        out.actuation_force, std::abs(moment) / std::max({m.sheet.length, m.sheet.width, 1e-3}));
  }
  for (DriveDef& d : out.drives) {
    d.stiffness = 0;
    d.damping = 0;
    d.travel = 0;
    d.speed = 0;
  }
  return out;
}

}  // namespace finseg
