// Curvature correction of a plate cell (docs/stiffness.md, "Cell curvature correction"): the
// energy that makes a segment's joints store Kirchhoff's bending energy for any uniform
// curvature, on any segmentation, Poisson coupling included.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "core/types.hpp"

namespace finseg {

/// One side of a plate cell: the force element there and how its rotation reads in the
/// cell's frame. The element's rotation vector theta = log(R_FE) (frame F) gives the rotation
/// of the neighbour relative to the cell as sign * R_BF * theta, B the cell's body frame.
struct PlateCellSide {
  int element = -1;
  Mat3 R_BF = Mat3::Identity();  ///< the element's frame F in the cell's body frame
  double sign = 1;               ///< +1: the cell is the element's outer body; -1: inner
};

/// E = 1/2 Theta^T Q Theta, Theta the in-plane components (x, y of B) of the neighbours'
/// relative rotations, two per side, in `sides` order.
struct PlateCellDef {
  int body = -1;
  std::vector<PlateCellSide> sides;
  Eigen::MatrixXd Q;  ///< N m/rad, 2 sides x 2 sides
  /// True: a correction to the joints' bending (State::plate_correction_scale applies);
  /// false: the consistent cell Hessian, which holds the whole bending itself.
  bool correction = true;
};

/// Membrane correction of a cell (docs/stiffness.md, "Cell membrane correction"):
/// E = 1/2 delta^T Q delta, delta the in-plane components (x, y of the cell's frame B) of
/// each side's joint translation (the inner attachment point less the outer one), signed as
/// the neighbour's displacement relative to the cell; two per side, in `sides` order
/// (PlateCellSide::R_BF unused).
struct MembraneCellDef {
  int body = -1;
  std::vector<PlateCellSide> sides;
  Eigen::MatrixXd Q;  ///< N/m, 2 sides x 2 sides
};

}  // namespace finseg
