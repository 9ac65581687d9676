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
  double share = 0.5;  ///< a crease side's part of its energy that is this cell's (1 at a clamp)
  /// Part of the joint's strip (centroid to centroid across the side) inside this cell:
  /// d_own / (d_own + d_other), 1 at a clamp: a plate side's share of its energy, and its
  /// weight in the curvature fit with the joint's stiffness (docs/stiffness.md, "Shares in
  /// the fit"); the membrane correction's share.
  double strip_share = 0.5;
  /// A crease side: its fold is the crease law's, so it is no measurement of the curvature;
  /// only its twist spring (about `across_M`, the side's normal) counts in the joints' energy.
  bool crease = false;
  /// A crease whose law sits in series with the plate's bending spring across the side
  /// (PatternSheetSpec::crease_bending_in_series): the side stores that bending as a plate
  /// joint does, so it counts whole in the joints' energy (still not in the fit).
  bool crease_bends = false;
  Vec2 across_M = Vec2::Zero();
};

/// Q such that, for every uniform curvature, joints plus correction store Kirchhoff's energy
/// area * 1/2 kappa^T C kappa, C = D [[1, nu, 0], [nu, 1, 0], [0, 0, 2 (1 - nu)]]: the cell's
/// curvature is fitted to its sides' rotations (weighted least squares), components the
/// sides do not see are condensed out (free, as at a free edge).
PlateCellDef plate_cell_correction(int body, double area,
                                   const std::vector<CellSideGeometry>& sides, double D, double nu);

/// One side of a cell for the membrane correction, on the flat sheet.
struct MembraneSideGeometry {
  PlateCellSide side;       ///< element and sign (+1: the cell is the element's outer body)
  Vec2 d_M = Vec2::Zero();  ///< as CellSideGeometry::d_M, m
  Eigen::Matrix2d K_M = Eigen::Matrix2d::Zero();  ///< joint's in-plane stiffness, cell axes, N/m
  double share =
      0.5;  ///< part of the joint's energy that is this cell's: CellSideGeometry::strip_share
};

/// Q such that, for every uniform in-plane strain, joints plus correction store the plane-
/// stress energy area * 1/2 e^T C e, C = E t / (1 - nu^2) [[1, nu, 0], [nu, 1, 0], [0, 0,
/// (1 - nu) / 2]] (engineering shear): the joints alone have no Poisson coupling and, on a
/// grid, half the shear (each direction's joints see half the shear angle). The strain is
/// fitted to the sides' joint translations; unseen components condensed out.
MembraneCellDef membrane_cell_correction(int body, double area,
                                         const std::vector<MembraneSideGeometry>& sides, double E,
                                         double nu, double t);

/// The largest ratio, over uniform strains, of the energy the cell's joints store to the
/// plane-stress energy (C as above): 1 on rectangles (pure shear at 45 deg), above 1 on skewed
/// cells, whose joints also see the strain along their sides.
double membrane_joint_excess(double area, const std::vector<MembraneSideGeometry>& sides, double E,
                             double nu, double t);

}  // namespace finseg
