// A crease pattern cut into segments (docs/fold.md, "Segments"): quadrilaterals into the grid
// of their bilinear map (n_u x n_v cells), triangles into n^2 triangles of the barycentric
// grid, faces of more sides into a fan of triangles from the centroid, each cut likewise. The
// cells along a pattern edge are the same seen from both faces, so neighbouring faces meet
// side to side. Lengths in m.
#pragma once

#include <string>
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

/// How faces are cut. The cells along an edge are shared by opposite sides of a
/// quadrilateral and by all sides of a triangle or larger face (and both edges of a seam),
/// so each such class of edges gets one count: `n`, or with `segment_size` the fewest cells
/// that keep every cell side along each edge of the class at most that long.
struct Subdivision {
  int n = 2;                ///< cells along every edge when segment_size is 0
  double segment_size = 0;  ///< m; > 0: target largest cell side along the edges
  /// >= 1: along an edge of quadrilaterals only, the cells are graded geometrically towards an
  /// end that lies on another, folded crease (M, V, or F/U with a fold angle), the middle
  /// cell `crease_refinement` times the one at that end; 1: uniform.
  double crease_refinement = 1;
  /// True: every quadrilateral cell further cut into four triangles about its centre (the mean
  /// of its corners), which bend without stretching where a grid of rigid quadrilaterals
  /// cannot (docs/fold.md, "Triangle cells").
  bool triangles = false;
};

/// Cells along each pattern edge for `s` (0 for edges of no face); throws InputError naming
/// `source` and `field` when an edge would need more than `max_cells` cells.
std::vector<int> edge_cell_counts(const CreasePattern& p, const Subdivision& s,
                                  const std::string& source = "<api>",
                                  const std::string& field = "segment_size", int max_cells = 4096);

/// Number of cells subdivide_pattern makes, from the edge counts (memory checks); `triangles`
/// as Subdivision::triangles.
double planned_cell_count(const CreasePattern& p, const std::vector<int>& edge_counts,
                          bool triangles = false);

/// Cuts every face of `p` (validated, edge faces derived) as `s` says. Folded
/// positions of new vertices are interpolated in their face (linear on triangles, bilinear
/// on quadrilaterals), so planar folded faces stay planar. The two edges of a seam get
/// matching points (the same fractions of their length), and a link per pair of sides.
SegmentMesh subdivide_pattern(const CreasePattern& p, const Subdivision& s);

/// Cuts every face of `p` (validated, edge faces derived) into n x n cells, n >= 1. Folded
/// positions of new vertices are interpolated in their face (linear on triangles, bilinear
/// on quadrilaterals), so planar folded faces stay planar. The two edges of a seam get
/// matching points (the same fractions of their length), and a link per pair of sides.
SegmentMesh subdivide_pattern(const CreasePattern& p, int n);

}  // namespace finseg
