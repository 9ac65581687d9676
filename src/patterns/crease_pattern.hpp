// A crease pattern: the flat sheet cut into convex polygonal faces, with the edges between
// them marked as creases, boundaries, cuts or joins (the model of a FOLD file, docs/fold.md).
// Lengths in m. The later subdivision into segments reads this type; it knows no JSON.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace finseg {

/// FOLD's edges_assignment letters.
enum class EdgeAssignment : char {
  Mountain = 'M',
  Valley = 'V',
  Flat = 'F',        ///< crease present but not folded
  Boundary = 'B',    ///< edge of the sheet, one face
  Unassigned = 'U',  ///< crease of unknown direction
  Cut = 'C',         ///< slit: the two faces are not connected
  Join = 'J',        ///< not a crease: the two faces are one piece of sheet
};

/// True for M, V, F, U: a crease, which must have a face on each side.
bool is_crease(EdgeAssignment a);

/// The assignment of FOLD letter `c`, or false if `c` is not one of MVFBUCJ.
bool assignment_from_letter(char c, EdgeAssignment& out);

/// One edge of the pattern.
struct PatternEdge {
  std::array<int, 2> vertices{-1, -1};  ///< endpoints u -> v (vertex indices)
  EdgeAssignment assignment = EdgeAssignment::Unassigned;
  /// Fold angle in rad, FOLD's sign convention: the deviation from flat, positive for a
  /// valley (the faces' normals, +z of the flat pattern, turn towards each other), negative
  /// for a mountain; 0 when the file gives none (CreasePattern::has_fold_angles).
  double fold_angle = 0;
  /// Derived: the face on the left of u -> v (the face that runs u -> v counter-clockwise)
  /// and the face on the right; -1 where there is none.
  std::array<int, 2> faces{-1, -1};
  int face_count() const { return (faces[0] >= 0) + (faces[1] >= 0); }
};

/// File-level description carried through read and write.
struct PatternMeta {
  double file_spec = 1.1;    ///< FOLD version the file declared (1.1 if it declared none)
  std::string file_creator;  ///< software that wrote the file
  std::string frame_title;   ///< title of the crease-pattern frame
};

/// A further named placement of the pattern's vertices in 3-D (a later foldedForm frame of a
/// FOLD file), e.g. the deployed form that a shape probe compares a run with. Lengths in m.
struct PatternShape {
  std::string title;  ///< the frame's frame_title, else "file_frames[k]"
  std::vector<Vec3> vertices_m;
};

/// The crease pattern. Faces are vertex loops, counter-clockwise in the flat coordinates.
struct CreasePattern {
  PatternMeta meta;
  std::vector<Vec2> vertices_flat_m;    ///< flat (unfolded) coordinates, m
  std::vector<Vec3> vertices_folded_m;  ///< folded 3-D coordinates, m; empty if not given
  std::vector<PatternShape> shapes;     ///< further folded forms (distinct titles)
  std::vector<std::vector<int>> faces;  ///< vertex indices, counter-clockwise
  std::vector<PatternEdge> edges;
  bool has_fold_angles = false;  ///< the file gave edges_foldAngle
  /// Seams: pairs of boundary edges that are the same line of the structure (a tube rolled
  /// from a rectangle), joined with opposite orientation: edge a's u -> v meets edge b's
  /// v -> u. FOLD's custom field `finseg:seams` (docs/fold.md).
  std::vector<std::array<int, 2>> seams;
};

/// Fills PatternEdge::faces from the face loops. Throws InputError(source, field, ...) naming
/// the face or edge index where a face side is not an edge, an edge has more than two faces
/// or two faces run an edge in the same direction (inconsistent orientation).
void derive_edge_faces(CreasePattern& p, const std::string& source);

/// Edges made from the face sides when a file gives none: a side of one face is a boundary
/// (B), a side shared by two faces a flat crease (F), fold angle 0. Ordered by first
/// appearance in the face loops.
std::vector<PatternEdge> edges_from_faces(const std::vector<std::vector<int>>& faces);

}  // namespace finseg
