#include "model/state.hpp"

namespace finseg {

State initial_state(const Model& model) {
  State s;
  const size_t n = model.bodies.size();
  s.p_W.resize(n);
  s.R_WB.resize(n);
  s.v_W.assign(n, Vec3::Zero());
  s.w_W.assign(n, Vec3::Zero());
  for (size_t i = 0; i < n; ++i) {
    s.p_W[i] = model.bodies[i].p0_W;
    s.R_WB[i] = model.bodies[i].R0_WB;
  }
  s.drive_s.assign(model.drives.size(), 0.0);
  s.history.assign(model.elements.size(), ElementHistory{});
  for (size_t k = 0; k < model.elements.size(); ++k) {
    const int c = model.elements[k].crease;
    if (c >= 0) s.history[k].fold_angle = model.creases[c].initial_fold_angle;
  }
  for (const ChamberDef& c : model.chambers) s.chambers.push_back(initial_gas(c));
  return s;
}

ChamberGas initial_gas(const ChamberDef& c) {
  ChamberGas g;
  g.volume = c.initial_volume;
  g.temperature = c.temperature;
  if (c.gas == GasModel::Prescribed) {
    g.pressure = c.prescribed.at.empty() ? c.prescribed.pressure : c.prescribed.pressures.front();
    return g;
  }
  g.pressure = c.initial_pressure;
  g.mass = c.initial_pressure * c.initial_volume / (c.gas_constant * c.temperature);
  g.energy = c.initial_pressure * c.initial_volume / (c.gamma - 1);
  return g;
}

}  // namespace finseg
