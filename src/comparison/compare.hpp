// Simulation against repeated measurements of a pull test (paper section 4.4, Fig. 23):
// spline resampling on the common displacement range, mean and spread of the measurements,
// difference curve and the error at the peak force. docs/compare.md gives the CSV format.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace finseg {

/// A force-displacement curve read from a CSV file, in SI units.
struct ForceCurve {
  std::string source;              ///< file it came from
  std::vector<double> x;           ///< displacement, m, strictly increasing
  std::vector<double> force;       ///< N
  std::string x_column, y_column;  ///< header names used
  std::vector<std::string> notes;  ///< e.g. a column without a unit suffix read in mm or N
};

/// Reads a curve. Cells are separated by ',' or, when the header line holds a ';', by ';'
/// (a ',' is then a decimal comma). Columns: `x_column` / `y_column` when given, else the
/// first column whose name ends in `_mm` or `_m` (displacement) and the first ending in `_N`
/// or `_mN` (force), else the first column and the first other one; the suffix sets the unit,
/// a column without one is read in mm or N (a note says so). '#' starts a comment, blank
/// lines are skipped. Throws InputError(file, "line N ..." or "header", ...) on a missing
/// column, a header of numbers, a value that is not a finite number or whose magnitude
/// reaches 1e100 (SI), a displacement that does not strictly increase, or fewer than 4 points.
ForceCurve read_force_curve(const std::string& path, const std::string& x_column = "",
                            const std::string& y_column = "");

/// A curve's force at the displacements `x` (m), from the not-a-knot cubic spline through its
/// points (MATLAB's `spline`); `x` inside the curve's range.
std::vector<double> resample_curve(const ForceCurve& curve, const std::vector<double>& x);

/// Repeated measurements on one displacement grid: each resampled, and their mean, sample
/// standard deviation (n - 1; 0 for one measurement), minimum and maximum at each point, N.
struct MeasuredSpread {
  std::vector<std::vector<double>> runs;
  std::vector<double> mean, stddev, min, max;
};

/// Resamples every measurement at `x` (resample_curve) and builds their spread.
MeasuredSpread measured_spread(const std::vector<ForceCurve>& runs, const std::vector<double>& x);

/// Result of compare_curves; all curves on the same displacement grid.
struct Comparison {
  std::vector<double> x;                  ///< common grid, m
  std::vector<double> simulation;         ///< N
  std::vector<std::vector<double>> runs;  ///< each measurement resampled, N
  std::vector<double> mean, stddev;       ///< mean and sample standard deviation, N
  std::vector<double> min, max;           ///< envelope of the measurements, N
  std::vector<double> difference;         ///< simulation - mean, N
  /// "deployment" when both curves have a deployment peak (probes/deployment_peak.hpp),
  /// else "largest" (the largest force of each curve on the grid).
  std::string peak_rule = "deployment";
  double sim_peak = 0, sim_peak_x = 0;    ///< simulated peak force and where, N and m
  double mean_peak = 0, mean_peak_x = 0;  ///< peak of the measured mean and where
  double peak_error = 0;  ///< (sim_peak - mean_peak) / mean_peak (paper's figure of merit)
  double sim_max = 0, sim_max_x = 0;      ///< largest simulated force on the grid and where
  double mean_max = 0, mean_max_x = 0;    ///< largest mean force on the grid and where
  double rms_error = 0;                   ///< sqrt(mean(difference^2)) over the grid, N
  double max_error = 0, max_error_x = 0;  ///< largest |difference| and where, N and m
};

/// Displacement window of a comparison, m: the grid is cut to it (infinite: no cut).
struct CompareWindow {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
};

/// Resamples every curve with a not-a-knot cubic spline at `samples` equally spaced points
/// of the common displacement range [max of the starts, min of the ends] cut to `window`,
/// and compares; the peaks are deployment peaks (find_deployment_peak over the grid), or the
/// largest forces when either curve has none. Throws InputError when there is no
/// measurement, the ranges do not overlap (or miss the window), samples < 2, or a result is
/// not finite.
Comparison compare_curves(const ForceCurve& simulation, const std::vector<ForceCurve>& runs,
                          int samples = 201, const CompareWindow& window = {});

/// Writes `dir`/comparison.csv, comparison.json and, when `plot`, comparison.png (Fig. 23:
/// simulation, each measurement, mean and difference). Creates `dir` if needed.
void write_comparison(const Comparison& c, const ForceCurve& simulation,
                      const std::vector<ForceCurve>& runs, const std::string& dir, bool plot);

}  // namespace finseg
