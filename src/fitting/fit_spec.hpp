// Fit files (docs/fit.md): which scene parameters (`--set` paths) to fit, their start
// values and bounds, the measured force-displacement curves to fit them to and the
// least-squares settings.
#pragma once

#include <string>
#include <vector>

#include "comparison/compare.hpp"
#include "scene/overrides.hpp"

namespace finseg {

/// One fitted parameter: a `--set` path (or several that take the same value, e.g. the
/// stiffness of every crease), its start value and bounds (in the scene's units) and the
/// scale the optimiser divides it by (default |initial|).
struct FitParameter {
  std::string path;                ///< the first path: the parameter's name
  std::vector<std::string> paths;  ///< every path set to the value
  double initial = 0;
  double lower = -INFINITY, upper = INFINITY;
  double scale = 1;
};

/// One measured test: the scene that simulates it (with its own fixed overrides), the drive
/// probe compared, the repeated measurements and the displacements the residuals are taken at.
struct FitCurve {
  std::string scene;             ///< resolved against the fit file's folder
  std::vector<Override> set;     ///< fixed overrides of this curve, before the fitted ones
  std::string probe;             ///< drive probe name; empty: the scene's first drive probe
  std::vector<ForceCurve> runs;  ///< repeated measurements, read when the file is read
  CompareWindow window;          ///< m
  int samples = 0;               ///< 0: the first measurement's own displacements
  /// Displacements the residuals are taken at, m: the first measurement's own inside the
  /// measurements' common range and the window, or `samples` equally spaced points there.
  std::vector<double> x;
};

/// Least-squares settings (Ceres' Levenberg-Marquardt with bounds).
struct FitSolverSettings {
  int max_iterations = 50;
  double relative_step = 1e-4;  ///< central differences: h = relative_step * |x / scale|
  double function_tolerance = 1e-10, parameter_tolerance = 1e-8, gradient_tolerance = 1e-12;
};

/// A fit as read from its file.
struct FitSpec {
  std::string file;  ///< the fit file, for messages
  std::vector<FitParameter> parameters;
  std::vector<FitCurve> curves;
  FitSolverSettings solver;
};

/// Reads and validates a fit file and the measurement files it names. Throws InputError
/// naming the file, the field and the allowed range.
FitSpec read_fit(const std::string& path);

}  // namespace finseg
