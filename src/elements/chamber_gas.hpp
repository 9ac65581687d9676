// Gas in chambers (docs/gas.md): the volume of each chamber now, the pressure its gas model
// gives for a trial state, the pressure forces on its faces, and the gas state committed
// after each accepted step.
#pragma once

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

class Assembler;

/// Checks that every chamber closes at the initial poses (with its end plates) and fills
/// ChamberDef::initial_volume and plate_volume. Throws InputError naming the open edge, or
/// a chamber whose volume is not positive (faces oriented inwards). Call after the bodies
/// and chambers are final.
void prepare_chambers(Model& model);

/// Volume enclosed by chamber `c`'s node surface at `state`, m^3.
double chamber_volume_now(const Model& model, const State& state, int c);

/// The gas of chamber `def` as it would be committed at time (or static parameter) `t` with
/// volume `volume` (m^3), starting from the record `last` of the last accepted step. The
/// mass is advanced explicitly (inflow integrated exactly, vent flow at `last`), the energy
/// implicitly with the trapezoidal work (p_last + p) dV / 2, so the pressure is a function
/// of the trial volume alone.
ChamberGas gas_after(const ChamberDef& def, const ChamberGas& last, double t, double volume,
                     double load_scale, bool quasi_static);

/// dp/dV of gas_after at the same arguments, Pa/m^3: the gas's stiffness against a change of
/// the trial volume (0 for a prescribed pressure).
double gas_pressure_slope(const ChamberDef& def, const ChamberGas& last, double t, double volume,
                          double load_scale, bool quasi_static);

/// Adds every chamber's pressure forces p dV/dq, with their Jacobian at fixed p when wanted
/// (the dependence of p on V is the solvers': solvers/volume_stiffness.hpp).
void add_chamber_pressures(const Model& model, const State& state, Assembler& as);

/// Advances State::chambers to the state's time and poses (after an accepted step).
void commit_chamber_gas(const Model& model, State& state);

/// Largest pressure force of a chamber face at the full load (static solvers' force scale), N.
double largest_chamber_force(const Model& model);

/// Enters (on) or leaves the static solver's quasi-static gas models; the gas clocks restart
/// at the state's t when the meaning of t changes.
void set_quasi_static(State& state, bool on);

/// Largest step (s) that keeps the vents' explicit mass update accurate: 2 % of the mass
/// over the current vent flow of any chamber; infinity without vent flow.
double gas_step_limit(const Model& model, const State& state);

}  // namespace finseg
