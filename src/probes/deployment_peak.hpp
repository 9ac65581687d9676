// The deployment peak of a pull curve (docs/zigzag.md, "Deployment peak"): the largest force
// the structure needs to get past a barrier while it deploys, as distinct from the force at
// the end of the travel, where a fully opened strip is pulled taut and the force rises
// without falling again.
#pragma once

#include <limits>
#include <vector>

namespace finseg {

/// Share of the window's force range by which the force must fall after a peak: 5 %.
constexpr double kDefaultPeakDrop = 0.05;

/// Result of find_deployment_peak; positions in the curve's displacement unit.
struct DeploymentPeak {
  bool found = false;  ///< false: the force never falls back (e.g. it rises over the window)
  double force = std::numeric_limits<double>::quiet_NaN();
  double x = std::numeric_limits<double>::quiet_NaN();  ///< where it occurs
  int index = -1;                                       ///< sample index in the curve
};

/// Rule: among the samples with window_lo <= x <= window_hi, a sample is a peak when the
/// force rises to it (it is not the window's first sample and not below the one before) and
/// afterwards falls by at least `drop` x (largest - smallest force in the window) before it
/// rises above the sample's own force again, all inside the window. The deployment peak is
/// the largest such force (the first of equal ones). A force still rising at the window's
/// end (a strip pulled taut) is therefore never a peak. `x` must be sorted.
DeploymentPeak find_deployment_peak(const std::vector<double>& x, const std::vector<double>& force,
                                    double window_lo, double window_hi,
                                    double drop = kDefaultPeakDrop);

/// Index of the largest force (the first of equal ones) with window_lo <= x <= window_hi;
/// -1 if no sample lies in the window.
int max_force_index(const std::vector<double>& x, const std::vector<double>& force,
                    double window_lo, double window_hi);

}  // namespace finseg
