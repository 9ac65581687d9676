// Validation of a crease pattern before it is cut into segments (docs/fold.md lists every
// rule). Each refusal is an InputError naming the source file, the FOLD field with the
// index of the offending vertex, face or edge, and what was expected.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "patterns/crease_pattern.hpp"

namespace finseg {

/// Relative tolerances of the geometric checks (docs/fold.md, "Refusals").
struct PatternTolerances {
  double planarity = 1e-6;    ///< folded face off its best-fit plane / face diameter
  double area = 1e-10;        ///< face area / face diameter^2 below which a face is degenerate
  double convexity = 1e-9;    ///< reflex-corner sine tolerated (straight corners are allowed)
  double touch = 1e-9;        ///< distance / pattern size at which two edges count as touching
  double seam_length = 1e-9;  ///< relative difference of a seam's two edge lengths
  double seam_gap = 1e-6;     ///< folded distance of a seam's joined ends / pattern size
};

/// Checks everything and fills each edge's `faces`: indices in range, faces of >= 3 distinct
/// vertices, the edge-face adjacency (manifold, consistently oriented), assignment against
/// adjacency and fold angle, face geometry (area, counter-clockwise, convex, planar when
/// folded), crossing edges and seams (boundary edges, each in one seam, equal lengths,
/// faces on the same side so the sheet keeps its orientation, ends meeting when folded). Throws
/// InputError(source, field[index], why).
void validate_pattern(CreasePattern& p, const std::string& source,
                      const PatternTolerances& tol = {});

/// First pair (i < j, smallest i then j) of edges that intersect or touch other than at a
/// shared endpoint, in the flat coordinates; two edges from one vertex count when they
/// overlap along a line. A uniform grid makes it O(n) for evenly sized edges; `touch` is an
/// absolute distance, m.
std::optional<std::array<int, 2>> find_edge_crossing(const std::vector<Vec2>& xy,
                                                     const std::vector<PatternEdge>& edges,
                                                     double touch);

/// Signed fold angle of interior edge `e` measured from the folded 3-D coordinates, rad, in
/// FOLD's convention (valley positive). Needs vertices_folded_m and two faces on the edge.
double measured_fold_angle(const CreasePattern& p, int e);

/// The same across seam `k`, along its edge a (u -> v), from the faces on its two edges.
double measured_seam_fold_angle(const CreasePattern& p, int k);

}  // namespace finseg
