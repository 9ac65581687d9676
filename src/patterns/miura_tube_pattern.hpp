// The Miura-ori tube (docs/fold.md, "The Miura tube"; docs/gas.md, "The Z-folded tube"): a
// two-row Miura strip and its mirror image about the plane z = 0, seamed along their two
// boundary ridge lines, make a closed tube along x whose every cross-section is the same
// rhombus. It folds rigidly (one degree of freedom) from flat (no volume) to an accordion
// stowed along its length (no volume), through the largest volume at a fold angle of 45 deg.
#pragma once

#include <vector>

#include "patterns/crease_pattern.hpp"
#include "patterns/miura_pattern.hpp"

namespace finseg {

/// Geometry of the Miura tube. SI units, angles in rad. Each of the two sheets is the
/// Miura sheet `miura_tube_sheet` (2 rows, side_a straight in the flat sheet, side_b zigzag).
struct MiuraTubeSpec {
  int columns = 8;                     ///< panel columns along the tube (x), 1..1000
  double side_a = 0.02;                ///< m: the rhombic section's side (across the tube)
  double side_b = 0.02;                ///< m: the zigzag side, along the tube
  double sector_angle = kPi / 3;       ///< gamma, the parallelograms' acute angle, (0, pi/2)
  double fold_angle = 80 * kDegToRad;  ///< theta stowed (miura_tube_shape), (0, pi/2)
  bool caps = true;                    ///< close both ends by rhombic cap faces seamed on
};

/// The sheet z >= 0 as a Miura sheet: rows 2, the spec's columns, sides, angles.
MiuraSpec miura_tube_sheet(const MiuraTubeSpec& s);

/// Closed-form shape at fold angle theta (Schenk and Guest's theta of each sheet, the panels'
/// angle to the plane z = 0; 0 flat, pi/2 fully folded), m: the section is a rhombus of
/// half-diagonals `half_width` (L, along y) and `half_height` (H, along z), sides side_a
/// (L^2 + H^2 = side_a^2); `length` = columns S along x.
struct MiuraTubeShape {
  double half_width = 0, half_height = 0, length = 0;
};
MiuraTubeShape miura_tube_shape(const MiuraTubeSpec& s, double theta);

/// Enclosed volume at theta, m^3: the rhombus 2 L H times the length columns S (the caps
/// are planar, in planes x = const).
double miura_tube_volume(const MiuraTubeSpec& s, double theta);

/// Largest volume over theta, m^3: columns side_b side_a^2 sin^2(gamma), at theta = 45 deg
/// for every gamma (derived in docs/fold.md).
double miura_tube_max_volume(const MiuraTubeSpec& s);

/// The pattern at the stowed fold angle. Development: the sheet z >= 0 at vertex (i, j) ->
/// (j b sin gamma, i a + [j odd] b cos gamma) (Miura rows i = 0..2, columns j = 0..columns),
/// the sheet z <= 0 its mirror image below it (y -> -y - gap), the caps beside them. Folded:
/// vertex (i, j) at (j S, i L + [j odd] V, +-[i == 1] H) (miura_cell of miura_tube_sheet), the
/// ridge lines i = 0 and i = 2 seamed to the mirror's, each cap's four sides seamed to the
/// tube's end edges (caps at x = 0 and x = columns S). Faces column by column: column j is
/// faces 4 j .. 4 j + 3 (upper row 0, upper row 1, lower row 0, lower row 1), then the cap at
/// x = 0 and the cap at the far end. Creases M/V by the sign of the measured fold angle, with
/// it. Throws InputError("<api>", field, ...) for a spec out of range.
CreasePattern miura_tube_crease_pattern(const MiuraTubeSpec& s);

/// The 0-based faces of column j (0 .. columns - 1).
std::vector<int> miura_tube_column_faces(const MiuraTubeSpec& s, int column);

/// The 0-based face of the cap at the fixed end (end 0, x = 0) or the free end (end 1);
/// throws InputError when the spec has no caps.
int miura_tube_cap_face(const MiuraTubeSpec& s, int end);

/// The folded position of vertex (sheet 0 upper / 1 lower, row i, column j) at theta, m.
Vec3 miura_tube_vertex(const MiuraTubeSpec& s, double theta, int sheet, int i, int j);

/// Pattern vertex index of (sheet, i, j).
int miura_tube_vertex_index(const MiuraTubeSpec& s, int sheet, int i, int j);

}  // namespace finseg
