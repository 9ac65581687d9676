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

}  // namespace finseg
