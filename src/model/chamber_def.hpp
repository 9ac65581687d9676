// Chambers (issue 13, docs/gas.md): closed volumes bounded by segment faces and fixed end
// plates, filled with gas whose pressure pushes on the faces.
#pragma once

#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/pressure_def.hpp"

namespace finseg {

/// One face of a chamber: the mid-surface rectangle of `body` with its outward normal
/// +z_B (outward_plus_z) or -z_B.
struct ChamberFace {
  int body = -1;
  bool outward_plus_z = true;
};

/// How a chamber's pressure is found. Prescribed: a given p(t) (or p(load scale));
/// Isothermal / Adiabatic: an ideal gas of uniform state whose mass and energy evolve.
enum class GasModel { Prescribed, Isothermal, Adiabatic };

/// Gas injected into a chamber (an inflator): mass flow (kg/s) and gas temperature (K),
/// linear in time between the rows, zero flow outside [at.front(), at.back()].
struct InflowDef {
  std::vector<double> at;           ///< s, strictly ascending
  std::vector<double> mass_flow;    ///< kg/s, >= 0, one per row
  std::vector<double> temperature;  ///< K, > 0, one per row
};

/// An orifice through which gas leaves to an ambient pressure (0: vacuum), isentropic
/// flow, choked or not; no flow back in.
struct VentDef {
  double area = 0;                   ///< m^2, > 0
  double discharge_coefficient = 1;  ///< -, (0, 1]
  double ambient_pressure = 0;       ///< Pa, >= 0
};

/// A vertex of a chamber's closed surface: a face corner moving with its body, or a fixed
/// end-plate vertex (body -1).
struct SurfaceVertex {
  int body = -1;
  Vec3 x = Vec3::Zero();  ///< m: the corner in the body frame, or the fixed world point
};

/// A closed volume: segment faces plus fixed plates, and the gas inside.
struct ChamberDef {
  std::string name;
  std::vector<ChamberFace> faces;
  /// Fixed planar polygons closing the surface (a base, a nozzle): world vertices in m,
  /// counter-clockwise seen from outside the chamber.
  std::vector<std::vector<Vec3>> end_plates;
  /// True: every loop of face edges that no other face or plate meets is closed by a cap, a
  /// polygon of those faces' own corners that moves with them (an end closed by the wall
  /// itself, of no stiffness: its pressure load goes to the corners).
  bool cap_open_ends = false;
  GasModel gas = GasModel::Prescribed;
  PressureDef prescribed;        ///< Prescribed: the pressure value or table (bodies unused)
  double gas_constant = 287.05;  ///< J/(kg K), specific gas constant (air)
  double gamma = 1.4;            ///< -, ratio of specific heats (> 1)
  double temperature = 293.15;   ///< K: initial gas temperature; isothermal: always
  double initial_pressure = 0;   ///< Pa, residual gas at the start (mass from p V / (R T))
  InflowDef inflow;              ///< empty: none
  std::vector<VentDef> vents;
  // Filled when the model is built (prepare_chambers): the closed surface of the faces, the
  // plates and the strips that bridge the gaps between them (docs/gas.md, "Volume"), as
  // vertex loops, and its volume at the initial poses, m^3.
  std::vector<SurfaceVertex> vertices;
  std::vector<std::vector<int>> loops;
  double initial_volume = 0;
};

/// Checks every chamber's numbers, tables and body indices; throws InputError naming
/// `source` and the field (chambers[i]...). Geometry (closedness) is checked by
/// prepare_chambers.
void validate_chambers(const std::vector<ChamberDef>& defs, int num_bodies,
                       const std::string& source);

}  // namespace finseg
