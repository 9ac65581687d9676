// Pressure loads (docs/pressure.md): a uniform pressure on a segment's mid-surface
// polygon as a follower force p A n_W at the centroid, n_W turning with the body.
#pragma once

#include "core/types.hpp"
#include "model/pressure_def.hpp"

namespace finseg {

class Assembler;
struct Model;
struct State;

/// Pressure of `def` now, Pa: load_scale * pressure, or the table at t or at load_scale.
double pressure_now(const PressureDef& def, double t, double load_scale);

/// Unit direction of the pressure force in body frame B: -z_B for PlusZ, +z_B for MinusZ.
Vec3 pressure_direction_B(PressureSide side);

/// Largest resultant p A of one pressure load over its bodies and table, N (solver scales).
double largest_pressure_force(const Model& model);

/// Adds a uniform pressure p (Pa) on the mid-surface rectangle of `body`, pressing on
/// `side`, as a follower force with its exact Jacobian.
void add_face_pressure(const Model& model, int body, PressureSide side, double p, Assembler& as);

/// Adds every pressure load of the model through the assembler (exact, unsymmetric
/// Jacobian). Potential energy: none (docs/pressure.md says why).
void add_pressure_loads(const Model& model, const State& state, Assembler& as);

}  // namespace finseg
