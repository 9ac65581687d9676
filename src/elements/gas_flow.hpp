// Ideal-gas flows of a chamber (docs/gas.md): the mass and enthalpy an inflator injects over
// a time interval, and the isentropic mass flow through a vent.
#pragma once

#include "model/chamber_def.hpp"

namespace finseg {

/// Mass (kg) and enthalpy (J) that enter between t0 and t1 (t0 <= t1).
struct InflowIntegral {
  double mass = 0;
  double enthalpy = 0;
};

/// Integral of the inflow table over [t0, t1], exact for the piecewise linear mass flow
/// and temperature (the enthalpy integrand cp mdot T is quadratic on each row interval).
InflowIntegral integrate_inflow(const InflowDef& inflow, double t0, double t1, double cp);

/// Mass injected over the whole table, kg.
double total_inflow_mass(const InflowDef& inflow);

/// Isentropic orifice flow out of gas at pressure p (Pa) and temperature T (K) to the vent's
/// ambient pressure, kg/s: choked when p_a / p is below the critical ratio
/// (2 / (gamma + 1))^(gamma / (gamma - 1)); zero when p <= p_a (no back flow).
double vent_mass_flow(const VentDef& vent, double p, double T, double gas_constant, double gamma);

}  // namespace finseg
