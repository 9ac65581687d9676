// The lay-flat tube (docs/fold.md, "The lay-flat tube"; docs/gas.md, "The Z-folded tube"): a
// rectangle rolled into a tube whose cross-section is a polygon linkage, stowed flattened
// (two layers a small gap apart, joined by two narrow side gussets) and closed at both ends by
// a flat seal, so that its folded coordinates are a closed surface of planar faces, an exact
// isometry of the development, whose volume grows when the gas rounds the section out.
#pragma once

#include "patterns/crease_pattern.hpp"

namespace finseg {

/// Geometry of the lay-flat tube. SI units.
struct FlatTubeSpec {
  int layer_facets = 4;  ///< facets across each layer, >= 1
  int rows = 6;          ///< rows along the tube, >= 3 (the first and last are the seals)
  double width = 0.05;   ///< flattened width of each layer, m
  double gap = 5e-4;     ///< the layers' distance apart = the gussets' height, m, (0, width)
  double length = 0.3;   ///< axial length, seals included, m
  /// Axial length of each seal row, m, (0, length / 2): short (a few gaps) so that the
  /// gussets' seal triangles, gap / 2 wide, are not slivers.
  double seal_length = 2e-3;
};

/// The pattern. Section corners, going round with the flat sheet's +z outwards: the top
/// layer's facets (width / layer_facets each, +x), the right gusset (gap), the bottom layer's
/// facets (-x), the left gusset. Development: these columns along x, starting in the middle of
/// the bottom layer (the seam along the tube, last column onto first, is then a flat joint),
/// rows along y. Folded: axis +y from y = 0, top layer at z = +gap / 2, bottom at -gap / 2,
/// gussets at x = +-width / 2. In the first and last rows (the seals, seal_length along the
/// axis) the layers meet at z = 0 on the end line, the gussets fold outwards in half there
/// (each seal cell of a gusset three triangles about the middle M of its end edge) so that
/// the seal line is width + gap long, and the layers' and gussets' end edges are seamed to
/// each other. Creases: the section's corner lines are mountains (flat, 0, between a layer's
/// facets; -90 degrees at the gussets), the seal rows' other lines by the sign of the measured
/// angle; straight rows meet at joins (J). Faces row by row, each row's columns in
/// development order, a seal row's gusset cells three triangles each (flat_tube_row_faces).
/// Throws InputError("<api>", field, ...) for a spec out of range.
CreasePattern flat_tube_crease_pattern(const FlatTubeSpec& s);

/// The 0-based faces of row `row` (0 .. rows - 1): 2 layer_facets + 2 in a straight row,
/// 2 layer_facets + 6 in a seal row (0 and rows - 1).
std::vector<int> flat_tube_row_faces(const FlatTubeSpec& s, int row);

/// Volume enclosed by the flattened tube, m^3: the straight rows' rectangle width x gap,
/// and each seal row a wedge whose section at s (0 at its inner edge, 1 at the end) is the
/// rectangle 2 g x (width + gap - 2 g), g = gap (1 - s) / 2:
///   gap (width (length - 2 seal_length) + 2 seal_length (width / 2 + gap / 6)).
double flat_tube_volume(const FlatTubeSpec& s);

/// The deployed section: the cyclic polygon (the largest area of the linkage, which a
/// uniform pressure seeks) of 2 layer_facets sides width / layer_facets and two of gap, m^2.
double flat_tube_round_area(const FlatTubeSpec& s);

}  // namespace finseg
