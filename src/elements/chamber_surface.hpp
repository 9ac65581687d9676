// The closed surface of a chamber (docs/gas.md, "Volume"): its faces' rectangles, its end
// plates, and the strips and corner patches that bridge the gaps the force elements open
// between neighbouring faces; the volume it encloses and the pressure forces that are the
// volume's exact gradient.
#pragma once

#include <vector>

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

class Assembler;

/// Fills def.vertices and def.loops from the initial poses. Corners closer than `tol` (m)
/// coincide. Every edge must meet one oppositely running edge of another face or plate end
/// to end; a face corner on a plate's edge becomes a plate vertex; a face corner inside
/// another face's edge (a T-junction) is refused (InputError naming `field`).
void build_chamber_surface(const Model& model, ChamberDef& def, double tol,
                           const std::string& field);

/// Volume enclosed by the surface at `state`, m^3 (each loop fanned into triangles from its
/// first vertex); `gradient`, when given, receives dV/dx of every vertex, m^2.
double surface_volume(const State& state, const ChamberDef& def,
                      std::vector<Vec3>* gradient = nullptr);

/// Adds the generalized force p dV/dq of pressure p (Pa) on the bodies: each corner takes
/// p dV/dx, with its moment about the body's centroid (on a face's rectangle this sums to
/// p A n at the centroid); when the assembler wants a Jacobian, also its derivative at fixed
/// p, p d2V/dq2 (the faces turning and moving apart under the pressure: a follower load).
/// The dependence of p on V is the solvers' (a rank-one term, docs/gas.md).
void add_surface_pressure(const State& state, const ChamberDef& def, double p, Assembler& as);

}  // namespace finseg
