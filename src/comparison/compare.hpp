// Simulation against repeated measurements of a pull test (paper section 4.4, Fig. 23):
// spline resampling on the common displacement range, mean and spread of the measurements,
// difference curve and the error at the peak force. docs/compare.md gives the CSV format.
#pragma once

#include <string>
#include <vector>

namespace finseg {

/// A force-displacement curve read from a CSV file, in SI units.
struct ForceCurve {
  std::string source;              ///< file it came from
  std::vector<double> x;           ///< displacement, m, strictly increasing
  std::vector<double> force;       ///< N
  std::string x_column, y_column;  ///< header names used
};

/// Reads a curve. Columns: `x_column` / `y_column` when given, else the first column whose
/// name ends in `_mm` or `_m` (displacement) and the first ending in `_N` or `_mN` (force);
/// the suffix sets the unit. '#' starts a comment, blank lines are skipped. Throws
/// InputError(file, "line N ..." or "header", ...) on a missing column, a value that is not a
/// finite number, a displacement that does not strictly increase, or fewer than 4 points.
ForceCurve read_force_curve(const std::string& path, const std::string& x_column = "",
                            const std::string& y_column = "");

/// Result of compare_curves; all curves on the same displacement grid.
struct Comparison {
  std::vector<double> x;                  ///< common grid, m
  std::vector<double> simulation;         ///< N
  std::vector<std::vector<double>> runs;  ///< each measurement resampled, N
  std::vector<double> mean, stddev;       ///< mean and sample standard deviation, N
  std::vector<double> min, max;           ///< envelope of the measurements, N
  std::vector<double> difference;         ///< simulation - mean, N
  double sim_peak = 0, sim_peak_x = 0;    ///< largest simulated force and where, N and m
  double mean_peak = 0, mean_peak_x = 0;  ///< largest mean force and where
  double peak_error = 0;  ///< (sim_peak - mean_peak) / mean_peak (paper's figure of merit)
  double rms_error = 0;   ///< sqrt(mean(difference^2)) over the grid, N
  double max_error = 0, max_error_x = 0;  ///< largest |difference| and where, N and m
};

/// Resamples every curve with a not-a-knot cubic spline at `samples` equally spaced points
/// of the common displacement range [max of the starts, min of the ends] and compares.
/// Throws InputError when there is no measurement, the ranges do not overlap or
/// samples < 2.
Comparison compare_curves(const ForceCurve& simulation, const std::vector<ForceCurve>& runs,
                          int samples = 201);

/// Writes `dir`/comparison.csv, comparison.json and, when `plot`, comparison.png (Fig. 23:
/// simulation, each measurement, mean and difference). Creates `dir` if needed.
void write_comparison(const Comparison& c, const ForceCurve& simulation,
                      const std::vector<ForceCurve>& runs, const std::string& dir, bool plot);

}  // namespace finseg
