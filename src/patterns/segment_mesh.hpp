// A crease pattern cut into segments: every face divided into n x n cells (quadrilaterals:
// the grid of their bilinear map; triangles: n^2 triangles of the barycentric grid; faces of
// more sides: a fan of triangles from the centroid, each cut likewise). Every pattern edge
// gets n cell sides, so neighbouring faces meet side to side. Lengths in m.
#pragma once

#include <vector>

#include "patterns/crease_pattern.hpp"

namespace finseg {

/// A side shared by two cells: `left` runs it a -> b counter-clockwise, `right` b -> a.
/// Across a seam the two cells have their own copies of the side's points: the right cell
/// runs b_right -> a_right (elsewhere a_right = a, b_right = b).
struct CellLink {
  int left = -1, right = -1;
  int a = -1, b = -1;     ///< mesh vertices
  int pattern_edge = -1;  ///< the pattern edge it lies on (left's edge on a seam), -1 inside
  int a_right = -1, b_right = -1;  ///< the right cell's vertices at a and b
  int seam = -1;                   ///< CreasePattern::seams index, -1 if none
};

struct SegmentMesh {
  std::vector<Vec2> flat_m;             ///< vertices on the flat sheet, m
  std::vector<Vec3> folded_m;           ///< folded positions (empty when the pattern has none)
  std::vector<std::vector<int>> cells;  ///< vertex loops, counter-clockwise
  std::vector<int> cell_face;           ///< pattern face of each cell
  std::vector<CellLink> links;          ///< sides shared by two cells (none across cuts, C)
};

/// Cuts every face of `p` (validated, edge faces derived) into n x n cells, n >= 1. Folded
/// positions of new vertices are interpolated in their face (linear on triangles, bilinear
/// on quadrilaterals), so planar folded faces stay planar. The two edges of a seam get
/// matching points (the same fractions of their length), and a link per pair of sides.
SegmentMesh subdivide_pattern(const CreasePattern& p, int n);

}  // namespace finseg
