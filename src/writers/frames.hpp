// Recorded configurations for animation writers (VTK series, HTML page).
#pragma once

#include <string>
#include <vector>

#include "core/types.hpp"

namespace finseg {

/// One recorded configuration of all bodies.
struct Frame {
  double t = 0;                        ///< time (s) or drive displacement (m) for quasi-static runs
  std::vector<Vec3> p_W;               ///< body centroids, m
  std::vector<Mat3> R_WB;              ///< body orientations
  std::vector<Vec3> contact_points_W;  ///< active contact points, m (may be empty)
};

/// An x-y curve shown beside an animation (e.g. gauge force against pull displacement).
struct Curve {
  std::string x_label, y_label;  ///< with units, e.g. "pull displacement [mm]"
  std::vector<double> x, y;      ///< one point per frame, same order as the frames
};

}  // namespace finseg
