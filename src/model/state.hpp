// State: where the structure is now (poses, velocities, time, history). Like MuJoCo's mjData.
// Solvers advance it; elements read it and never own it.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "model/model.hpp"

namespace finseg {

/// History carried by one force element between accepted steps.
struct ElementHistory {
  double fold_angle = 0;  ///< last accepted unwrapped fold angle (creases), rad
  int openings = 0;       ///< completed openings of the crease
  bool opened = false;    ///< currently past the opening threshold
  /// Last accepted relative rotation theta of a joint that resists turning (F components),
  /// rad, unwrapped: |theta| passes pi where the joint bends past a half turn. Zero while it
  /// is turned less than 2 rad (log R_FE is then the nearest anyway), for creases and for
  /// joints with no rotational stiffness.
  Vec3 rotation_F = Vec3::Zero();
};

/// What a dynamic solver carries from one step to the next besides the State proper, saved
/// at each output so that a run continued from a checkpoint takes the same steps.
struct SolverMemory {
  double dt = 0;                 ///< step the solver takes next, s (0: unknown)
  double next_output = 0;        ///< time of the next output, s
  double t_start = 0;            ///< explicit: time of step 0 (t = t_start + steps dt), s
  long steps = 0;                ///< explicit: steps taken since t_start
  double t = -1;                 ///< State::t when saved; ignored at any other time
  std::vector<Vec3> f_W, tau_W;  ///< explicit: forces the next step starts from, N, N m
  /// Generalized-alpha: vdot_n and the algorithmic acceleration a_n per DOF (empty: begin
  /// afresh), and the step h_n they belong to, s.
  std::vector<double> vdot, accel;
  double h_prev = 0;
};

/// Gas of one chamber at the last accepted step (docs/gas.md). Between steps the pressure
/// follows from this record, the elapsed time and the volume of the trial state.
struct ChamberGas {
  double t = 0;            ///< time of the record, s (static solver: its load or drive parameter)
  double mass = 0;         ///< kg
  double energy = 0;       ///< internal energy, J (adiabatic gas)
  double volume = 0;       ///< m^3
  double pressure = 0;     ///< Pa
  double temperature = 0;  ///< K
  double work = 0;         ///< work of the gas on the structure since the start, J
  double injected = 0;     ///< mass that came in since the start, kg
  double vented = 0;       ///< mass that left through the vents since the start, kg
};

struct State {
  double t = 0;                 ///< s (static solver: load or drive parameter)
  std::vector<Vec3> p_W;        ///< centroid positions, m
  std::vector<Mat3> R_WB;       ///< orientations
  std::vector<Vec3> v_W;        ///< centroid velocities, m/s
  std::vector<Vec3> w_W;        ///< angular velocities in world frame, rad/s
  std::vector<double> drive_s;  ///< displacement of each drive, m
  double load_scale = 1.0;      ///< multiplies loads and gravity (static load stepping)
  /// Multiplies the plate cells' curvature corrections: the static solver's way into the
  /// Poisson coupling of thin plates (docs/solvers.md, "Plates: the corrections last"); 1 else.
  double plate_correction_scale = 1.0;
  std::vector<ElementHistory> history;  ///< one per force element
  ContactState contact;                 ///< contact points' history (friction anchors)
  SolverMemory solver;                  ///< integrator memory (checkpoints, resume)
  std::vector<ChamberGas> chambers;     ///< one per Model::chambers
  /// Set by the static solver: t is a load or drive parameter, not time, and gas models give
  /// their quasi-static pressure (docs/gas.md).
  bool quasi_static = false;
};

/// State at t = 0: initial poses, zero velocities, initial crease angles.
State initial_state(const Model& model);

/// Gas of a chamber at t = 0: initial pressure and temperature in its initial volume.
ChamberGas initial_gas(const ChamberDef& chamber);

}  // namespace finseg
