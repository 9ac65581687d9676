// The Miura-ori crease pattern (docs/fold.md, "Generated patterns"): rows x columns of equal
// parallelograms, sides a (straight in the flat sheet, along y) and b (zigzag, sector angle
// gamma to the a sides), with the rigid-folding kinematics of Schenk and Guest (PNAS 110,
// 3276, 2013) for its folded form.
#pragma once

#include "patterns/crease_pattern.hpp"

namespace finseg {

/// Geometry of a Miura sheet. SI units, angles in rad.
struct MiuraSpec {
  int rows = 4;                   ///< parallelograms along y (a sides), >= 1
  int columns = 4;                ///< parallelograms along x (b sides), >= 1
  double side_a = 0.02;           ///< m
  double side_b = 0.02;           ///< m
  double sector_angle = kPi / 3;  ///< gamma, the parallelogram's acute angle, (0, pi/2)
  double fold_angle = kPi / 4;    ///< theta, panels to the xy plane when folded, [0, pi/2)
};

/// Outer dimensions of the folded sheet, m: x (across the zigzag), y, z (height).
struct MiuraDimensions {
  double x = 0, y = 0, z = 0;
};

/// Schenk and Guest's sizes of one parallelogram at fold angle theta, m: S (x extent of a b
/// side), L (y extent of an a side), V (y offset of a b side), H (height of an a side).
struct MiuraCell {
  double S = 0, L = 0, V = 0, H = 0;
};

/// S = b cos(theta) tan(gamma) / r, L = a sqrt(1 - sin^2 theta sin^2 gamma), V = b / r,
/// H = a sin(theta) sin(gamma), r = sqrt(1 + cos^2 theta tan^2 gamma).
MiuraCell miura_cell(const MiuraSpec& s, double theta);

/// Closed-form outer dimensions at fold angle `theta` (rad, 0 flat): x = columns S,
/// y = rows L + V, z = H (Schenk and Guest's S, L, V, H; V only where columns >= 1).
MiuraDimensions miura_dimensions(const MiuraSpec& s, double theta);

/// Fold angle theta (rad) of the sheet whose height is `z` (m): asin(z / (a sin gamma)).
double miura_theta_from_height(const MiuraSpec& s, double z);

/// The pattern: flat coordinates with vertex (i, j) at (j b sin gamma, i a + [j odd] b cos
/// gamma), faces row by row, edges from the faces (outline B), creases M/V with their fold
/// angles and the folded coordinates at `fold_angle`. Throws InputError("<api>", field, ...)
/// for a spec out of range.
CreasePattern miura_crease_pattern(const MiuraSpec& s);

}  // namespace finseg
