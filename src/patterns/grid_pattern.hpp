// A flat rectangular sheet cut into a grid of rectangles: the plate benchmarks' pattern and
// a large valid pattern for tests and benchmarks of the checks.
#pragma once

#include "patterns/crease_pattern.hpp"

namespace finseg {

/// nx x ny rectangles of dx x dy m, origin at (0, 0); the outline B, the cuts between
/// rectangles J (one piece of sheet, no crease). Vertex (i, j) (row i, column j) is
/// i (nx + 1) + j; faces row by row; edges: the horizontal then the vertical ones of each
/// grid line in turn.
CreasePattern grid_crease_pattern(int nx, int ny, double dx, double dy);

}  // namespace finseg
