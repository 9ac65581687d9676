// The curvature correction of one plate cell (docs/stiffness.md, "Cell curvature
// correction"): from the geometry of its sides, the matrix Q of its energy.
#pragma once

#include <vector>

#include "model/plate_cell_def.hpp"

namespace finseg {

/// One side of a cell, on the flat sheet.
struct CellSideGeometry {
  PlateCellSide side;
  Vec2 d_M = Vec2::Zero();  ///< cell centroid -> neighbour's centroid (or the clamped side's
                            ///< foot point), m
  double weight = 0;        ///< the joint's rotational stiffness about both in-plane axes, N m
  double share = 0.5;       ///< part of the joint's energy that is this cell's (1 at a clamp)
  /// A crease side: its fold is the crease law's, so it is no measurement of the curvature;
  /// only its twist spring (about `across_M`, the side's normal) counts in the joints' energy.
  bool crease = false;
  Vec2 across_M = Vec2::Zero();
  /// Rotation per unit curvature that the two cells' own tilts add to the centroid
  /// difference (midpoint_tilt of the neighbour less the cell's), rad m.
  Eigen::Matrix<double, 2, 3> tilt = Eigen::Matrix<double, 2, 3>::Zero();
};

/// The tilt of a cell whose side midpoints lie on w = 1/2 x^T kappa x (x from its centroid),
/// less the tilt of that paraboloid at the centroid, as a rotation vector (w_y, -w_x) per
/// kappa = (k_xx, k_yy, k_xy): zero for centrally symmetric cells, not for triangles.
Eigen::Matrix<double, 2, 3> midpoint_tilt(const std::vector<Vec2>& outline_B);

/// Q such that, for every uniform curvature, joints plus correction store Kirchhoff's energy
/// area * 1/2 kappa^T C kappa, C = D [[1, nu, 0], [nu, 1, 0], [0, 0, 2 (1 - nu)]]: the cell's
/// curvature is fitted to its sides' rotations (weighted least squares), components the
/// sides do not see are condensed out (free, as at a free edge).
PlateCellDef plate_cell_correction(int body, double area,
                                   const std::vector<CellSideGeometry>& sides, double D, double nu,
                                   bool tilt_free = false);

}  // namespace finseg
