#include "scene/state_start.hpp"

#include <algorithm>

#include "elements/chamber_surface.hpp"

namespace finseg {

Model model_starting_from(const Model& m, const State& s) {
  Model out = m;
  for (std::size_t b = 0; b < out.bodies.size(); ++b) {
    out.bodies[b].p0_W = s.p_W[b];
    out.bodies[b].R0_WB = s.R_WB[b];
  }
  for (std::size_t i = 0; i < out.drives.size(); ++i) {
    DriveDef& d = out.drives[i];
    // The drive continues from where it was: its target at the state's displacement is the
    // point's position there.
    d.start_W = s.p_W[d.body] + s.R_WB[d.body] * d.point_B - s.drive_s[i] * d.direction_W;
  }
  for (std::size_t e = 0; e < out.elements.size(); ++e) {
    const int c = out.elements[e].crease;
    if (c >= 0) out.creases[c].initial_fold_angle = s.history[e].fold_angle;
  }
  for (ChamberDef& def : out.chambers) def.initial_volume = surface_volume(s, def);
  return out;
}

State start_fresh_from(Scene& scene, State start) {
  start.t = 0;
  start.solver = SolverMemory{};
  std::fill(start.drive_s.begin(), start.drive_s.end(), 0.0);
  scene.model = model_starting_from(scene.model, start);
  return start;
}

}  // namespace finseg
