// A rectangle rolled into a tube of flat facets (docs/fold.md, "Seams"): the prismatic tube
// of an inflatable boom, closed around its circumference by a seam.
#pragma once

#include "patterns/crease_pattern.hpp"

namespace finseg {

/// `facets` (>= 3) strips of width 2 R sin(pi / facets) side by side along x, `rows` (>= 1)
/// rows along y over `length` (m); rolled about the y axis so that the strips' corners lie
/// on the circle of radius R (m) about it, x = R cos(theta), z = -R sin(theta), the normals
/// +z of the flat sheet outward. The lines between strips are mountain creases of
/// -360 / facets degrees, the lines between rows joins (J), and the first strip's free edge
/// is seamed to the last one's. Vertex (i, j), row line i, strip line j: i (facets + 1) + j.
CreasePattern tube_crease_pattern(int facets, int rows, double radius, double length);

/// The tube of tube_crease_pattern with its inner row lines turned into the creases of a
/// zigzag (a Z-folded boom): on row line i (1 .. rows - 1) the facet at angle phi (its
/// centre, theta of the rolled tube) gets the fold angle (-1)^i fold_angle cos(phi) (rad,
/// FOLD's sign: valley positive), the bend of the tube at that line towards +x or -x,
/// mountain or valley by its sign (flat, 0, where cos(phi) = 0 or fold_angle = 0). The folded
/// coordinates stay those of the straight tube: the creases' angles are targets (folding by
/// simulation), as a polygonal tube has no isometric zigzag with one crease loop per fold
/// (docs/gas.md). Both ends are closed by N-gon caps glued on by seams: 0-based face
/// rows * facets at y = 0, rows * facets + 1 at y = length.
CreasePattern zfolded_tube_crease_pattern(int facets, int rows, double radius, double length,
                                          double fold_angle);

}  // namespace finseg
