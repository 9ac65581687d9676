#include "generators/state_refinement.hpp"

#include <limits>

#include "core/error.hpp"
#include "model/segment_shape.hpp"

namespace finseg {

int carrying_body(const Model& coarse, const BodyDef& b) {
  if (!b.centroid_M) {
    throw InputError(coarse.source, "bodies", "a refined state needs segments cut from a sheet");
  }
  int best = -1;
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t c = 0; c < coarse.bodies.size(); ++c) {
    const BodyDef& cb = coarse.bodies[c];
    if (cb.panel != b.panel || !cb.centroid_M) continue;
    if (polygon_contains(material_outline(cb), *b.centroid_M, 0)) return static_cast<int>(c);
    const double d = (*cb.centroid_M - *b.centroid_M).norm();
    if (d < nearest) nearest = d, best = static_cast<int>(c);
  }
  if (best < 0) {
    throw InputError(coarse.source, "bodies",
                     "face " + std::to_string(b.panel + 1) + " has no segment in the coarse model");
  }
  return best;
}

State refine_state(const Model& coarse, const State& coarse_state, const Model& fine,
                   double fraction) {
  State s = initial_state(fine);
  for (size_t i = 0; i < fine.bodies.size(); ++i) {
    const size_t ci = static_cast<size_t>(carrying_body(coarse, fine.bodies[i]));
    const BodyDef& c = coarse.bodies[ci];
    // The carrying body's motion from its start: x -> R_move x + p_move.
    const Mat3 R_move = coarse_state.R_WB[ci] * c.R0_WB.transpose();
    s.R_WB[i] = R_move * fine.bodies[i].R0_WB;
    s.p_W[i] = coarse_state.p_W[ci] + R_move * (fine.bodies[i].p0_W - c.p0_W);
  }
  for (size_t k = 0; k < fine.elements.size(); ++k) {
    const int crease = fine.elements[k].crease;
    if (crease < 0) continue;
    const double target = fine.creases[static_cast<size_t>(crease)].target_fold_angle;
    if (target != 0) s.history[k].fold_angle = fraction * target;
  }
  return s;
}

}  // namespace finseg
