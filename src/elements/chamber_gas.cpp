#include "elements/chamber_gas.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "elements/chamber_surface.hpp"
#include "elements/chamber_volume.hpp"
#include "elements/gas_flow.hpp"
#include "elements/pressure.hpp"  // pressure_now

namespace finseg {
namespace {

double vent_flow(const ChamberDef& def, const ChamberGas& g) {
  double mdot = 0;
  for (const VentDef& v : def.vents) {
    mdot += vent_mass_flow(v, g.pressure, g.temperature, def.gas_constant, def.gamma);
  }
  return mdot;
}

// Quasi-static (static solver): the gas mass is the load parameter, m = m0 + lambda * the
// inflator's whole mass, at the chamber temperature.
ChamberGas quasi_static_gas(const ChamberDef& def, ChamberGas g, double volume, double load_scale) {
  const double m0 =
      def.initial_pressure * def.initial_volume / (def.gas_constant * def.temperature);
  g.injected = load_scale * total_inflow_mass(def.inflow);
  g.mass = m0 + g.injected;
  g.temperature = def.temperature;
  g.pressure = g.mass * def.gas_constant * def.temperature / volume;
  g.energy = g.pressure * volume / (def.gamma - 1);
  return g;
}

ChamberGas dynamic_gas(const ChamberDef& def, const ChamberGas& last, ChamberGas g, double t,
                       double volume) {
  const double dt = std::max(0.0, t - last.t);
  const double cp = def.gamma * def.gas_constant / (def.gamma - 1);
  const InflowIntegral in = integrate_inflow(def.inflow, last.t, std::max(t, last.t), cp);
  const double out = std::min(dt * vent_flow(def, last), last.mass + in.mass);
  g.injected = last.injected + in.mass;
  g.vented = last.vented + out;
  g.mass = last.mass + in.mass - out;
  if (def.gas == GasModel::Isothermal) {
    g.temperature = def.temperature;
    g.pressure = g.mass * def.gas_constant * def.temperature / volume;
    g.energy = g.pressure * volume / (def.gamma - 1);
    return g;
  }
  // U = U_last + H_in - H_out - (p_last + p) dV / 2 with p = (gamma - 1) U / V, solved for U.
  const double dV = volume - last.volume;
  const double rhs =
      last.energy + in.enthalpy - cp * last.temperature * out - 0.5 * last.pressure * dV;
  g.energy = std::max(0.0, rhs / (1 + 0.5 * (def.gamma - 1) * dV / volume));
  g.pressure = (def.gamma - 1) * g.energy / volume;
  const double cv = def.gas_constant / (def.gamma - 1);
  g.temperature = g.mass > 0 ? g.energy / (g.mass * cv) : def.temperature;
  return g;
}

}  // namespace

void prepare_chambers(Model& model) {
  const State state = initial_state(model);
  for (std::size_t c = 0; c < model.chambers.size(); ++c) {
    ChamberDef& def = model.chambers[c];
    const std::string field = fmt::format("chambers[{}].faces", c);
    // With caps the open ends close by construction; build_chamber_surface checks the rest.
    if (!def.cap_open_ends) check_chamber_closed(model, state, def.faces, def.end_plates, field);
    double longest = 0;
    for (const ChamberFace& f : def.faces) {
      longest = std::max(longest, 2 * outline_radius(model.bodies[f.body].outline_B));
    }
    build_chamber_surface(model, def, 1e-9 * longest, fmt::format("chambers[{}]", c));
    def.initial_volume = surface_volume(state, def);
    if (!(def.initial_volume > 0)) {
      throw InputError(model.source, field,
                       fmt::format("encloses {:.6g} m^3; the outward sides must point out of the "
                                   "chamber (a closed surface oriented inwards has a negative "
                                   "volume)",
                                   def.initial_volume));
    }
    double area = 0;
    for (const ChamberFace& f : def.faces) {
      area += segment_area(model.bodies[f.body]);
    }
    for (std::size_t v = 0; v < def.vents.size(); ++v) {
      if (def.vents[v].area >= area) {
        throw InputError(model.source, fmt::format("chambers[{}].vents[{}].area", c, v),
                         fmt::format("{:.6g} m^2; must be smaller than the chamber's face area "
                                     "{:.6g} m^2",
                                     def.vents[v].area, area));
      }
    }
  }
}

double chamber_volume_now(const Model& model, const State& state, int c) {
  return surface_volume(state, model.chambers[c]);
}

ChamberGas gas_after(const ChamberDef& def, const ChamberGas& last, double t, double volume,
                     double load_scale, bool quasi_static) {
  if (!(volume > 0)) {
    throw DivergenceError(fmt::format(
        "chamber '{}': its volume fell to {:.6g} m^3 (initial {:.6g} m^3): the surface has "
        "turned inside out",
        def.name, volume, def.initial_volume));
  }
  ChamberGas g = last;
  g.t = t;
  g.volume = volume;
  if (def.gas == GasModel::Prescribed) {
    g.pressure = pressure_now(def.prescribed, t, load_scale);
  } else if (quasi_static) {
    g = quasi_static_gas(def, g, volume, load_scale);
  } else {
    g = dynamic_gas(def, last, g, t, volume);
  }
  g.work = last.work + 0.5 * (last.pressure + g.pressure) * (volume - last.volume);
  return g;
}

double gas_pressure_slope(const ChamberDef& def, const ChamberGas& last, double t, double volume,
                          double load_scale, bool quasi_static) {
  if (def.gas == GasModel::Prescribed) return 0;
  const ChamberGas g = gas_after(def, last, t, volume, load_scale, quasi_static);
  // The mass does not follow the trial volume (inflow integrated, vents at `last`): an
  // isothermal or quasi-static gas has p = m R T / V.
  if (quasi_static || def.gas == GasModel::Isothermal) return -g.pressure / volume;
  // Adiabatic: U = rhs / den with rhs = U0 - p_last (V - V_last) / 2 and
  // den = 1 + (gamma - 1) (V - V_last) / (2 V); p = (gamma - 1) U / V.
  if (g.energy <= 0) return 0;  // clamped at an empty chamber
  const double dV = volume - last.volume;
  const double den = 1 + 0.5 * (def.gamma - 1) * dV / volume;
  const double rhs = g.energy * den;
  const double d_rhs = -0.5 * last.pressure;
  const double d_den = 0.5 * (def.gamma - 1) * last.volume / (volume * volume);
  const double dU = (d_rhs * den - rhs * d_den) / (den * den);
  return (def.gamma - 1) * (dU * volume - g.energy) / (volume * volume);
}

void add_chamber_pressures(const Model& model, const State& state, Assembler& as) {
  for (std::size_t c = 0; c < model.chambers.size(); ++c) {
    const ChamberDef& def = model.chambers[c];
    const double V = chamber_volume_now(model, state, static_cast<int>(c));
    const double p =
        gas_after(def, state.chambers[c], state.t, V, state.load_scale, state.quasi_static)
            .pressure;
    if (p != 0) add_surface_pressure(state, def, p, as);
  }
}

void commit_chamber_gas(const Model& model, State& state) {
  for (std::size_t c = 0; c < model.chambers.size(); ++c) {
    const double V = chamber_volume_now(model, state, static_cast<int>(c));
    state.chambers[c] = gas_after(model.chambers[c], state.chambers[c], state.t, V,
                                  state.load_scale, state.quasi_static);
  }
}

double largest_chamber_force(const Model& model) {
  double f = 0;
  for (const ChamberDef& def : model.chambers) {
    double p = def.prescribed.pressure;
    for (double q : def.prescribed.pressures) p = std::max(p, q);
    if (def.gas != GasModel::Prescribed) {
      const ChamberGas full = quasi_static_gas(def, initial_gas(def), def.initial_volume, 1.0);
      p = std::max(def.initial_pressure, full.pressure);
    }
    for (const ChamberFace& face : def.faces) {
      f = std::max(f, p * segment_area(model.bodies[face.body]));
    }
  }
  return f;
}

void set_quasi_static(State& state, bool on) {
  if (state.quasi_static == on) return;
  state.quasi_static = on;
  for (ChamberGas& g : state.chambers) g.t = state.t;
}

double gas_step_limit(const Model& model, const State& state) {
  double h = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < model.chambers.size(); ++c) {
    const double mdot = vent_flow(model.chambers[c], state.chambers[c]);
    if (mdot > 0) h = std::min(h, 0.02 * state.chambers[c].mass / mdot);
  }
  return h;
}

}  // namespace finseg
