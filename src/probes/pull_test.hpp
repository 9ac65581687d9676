// A pull test run to its end with what the zigzag examples, tests and benchmarks record at
// each output: gauge force, contact, panel bending, phases.
#pragma once

#include <vector>

#include "model/model.hpp"
#include "probes/deployment_peak.hpp"
#include "probes/deployment_phases.hpp"
#include "solvers/solver.hpp"

namespace finseg {

/// One recorded output (an equilibrium for the static solver) of a pull test.
struct PullSample {
  double displacement = 0;  ///< drive 0's displacement (the slide), m
  double force = 0;         ///< gauge force along the pull direction, N
  int active_contacts = 0;
  double max_penetration = 0;  ///< m
  double bend = 0;             ///< largest panel_bend_angle of the watched panels, rad
  bool finite = true;          ///< every pose and force finite
};

/// The whole pull: samples, solver counters, phases, the deployment peak and the largest force.
struct PullResult {
  std::vector<PullSample> samples;
  SolverStats stats;
  DeploymentPhases phases;
  /// Deployment peak (find_deployment_peak over [0, drive 0's deployed_at], or the whole
  /// travel when that is 0): the paper's figure of merit; `x` in m.
  DeploymentPeak deployment_peak;
  double peak_force = 0;         ///< largest force over the whole travel (not the above), N
  double peak_displacement = 0;  ///< m, where the largest force occurs
  double max_penetration = 0;    ///< over the whole pull, m
  bool all_finite = true;
};

/// Pulls along drive 0 of `model` (which must have one) and records every output: with the
/// static solver (the default) one equilibrium per drive step; with a dynamic solver a pull
/// at the drive's speed up to settings.t_end. `watched_panels` (0-based) are the panels whose
/// bending marks phase 3; `bend_threshold` in rad (detect_phases).
PullResult run_pull_test(const Model& model, const std::vector<int>& watched_panels,
                         double bend_threshold, const SolverSettings& settings = {});

}  // namespace finseg
