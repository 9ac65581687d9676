// The simulation side of a fit: runs each measured curve's scene in-process with the fitted
// values set as overrides and resamples the drive probe's force at the measured displacements.
#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "fitting/fit_spec.hpp"

namespace finseg {

/// Simulates the curves of a fit (each scene's text is read once).
class FitModel {
 public:
  explicit FitModel(const FitSpec& spec);

  /// Simulated force (N) of every curve at its displacements FitCurve::x, for the fitted
  /// parameters at `values` (scene units, in FitSpec::parameters order). Throws InputError
  /// when a scene refuses a value or has no such drive probe, DivergenceError when a run does
  /// not finish or its curve does not reach the measured displacements.
  std::vector<std::vector<double>> simulate(const std::vector<double>& values) const;

  /// Simulations run so far (one per curve per call of simulate).
  long simulations() const { return simulations_; }

 private:
  const FitSpec& spec_;
  std::vector<std::string> scene_text_;
  mutable std::atomic<long> simulations_{0};
};

}  // namespace finseg
