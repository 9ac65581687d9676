// Crease stiffness from the flap test (paper section 3.2, eq. 20): one flap fixed, the other
// pulled at lever L perpendicular to itself; M = F L against the opening angle, one curve per
// pressing time and opening count. The result is a crease data file (docs/crease-data.md)
// that a scene references with {type: measured, file: ...}, plus a plot like Fig. 17.
#pragma once

#include <string>

#include "core/cubic_spline.hpp"
#include "elements/crease_laws/crease_data.hpp"
#include "writers/plot.hpp"

namespace finseg {

/// What one identified curve says about the crease.
struct CreaseCurveSummary {
  double pressing_time = 0;  ///< s
  int opening = 1;
  int points = 0, repeats = 1;
  double theta_min_deg = 0, theta_max_deg = 0;  ///< measured range
  double rest_deg = 0;          ///< opening angle of zero moment (spline or its continuation); NaN
  double secant_stiffness = 0;  ///< K' = M(theta_max) / (theta_max - rest), eq. 20, N m/rad
  double tangent_start = 0, tangent_end = 0;  ///< dM/dtheta at the range ends, N m/rad
};

struct CreaseIdentification {
  CreaseData data;  ///< moments (N m), repeats averaged
  std::vector<CreaseCurveSummary> curves;
};

/// Summarises every curve of already-read flap data (read_crease_data gives M = F L).
CreaseIdentification identify_crease(const CreaseData& flap, SplineEnds ends);

/// Moment against opening angle, one line (spline) and the points per curve.
PlotSpec crease_plot(const CreaseIdentification& id, SplineEnds ends);

}  // namespace finseg
