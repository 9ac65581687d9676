// The folded cone's crease pattern (docs/fold.md, "Generated patterns"): the development of
// a truncated pyramid of 2 x pleats sides (the faceted cone), with radial creases on its
// generators (the pleats) and axial creases on zigzag rings between them (the axial folds),
// every ring vertex flat-foldable; mountains and valleys those of the fan fold (each
// generator one kind, alternating generator by generator; rings alternating facet by facet
// and ring by ring: the wall's flat-folded state is its facets stacked as a fan and
// Z-folded along the rings, docs/folding.md). Closed by a seam
// in the middle of a facet and, where asked, at either end by a disc (a rigid hub and a
// pleated band) seamed to the end ring: with both discs a closed surface. The folded
// coordinates are the deployed cone; the fold angles are the stowed targets (folding by
// simulation, docs/folding.md).
#pragma once

#include "patterns/crease_pattern.hpp"

namespace finseg {

/// Geometry of the folded cone. SI units, angles in rad.
struct ConeSpec {
  double base_radius = 0.1;  ///< circumscribed radius of the base, m
  double top_radius = 0.02;  ///< circumscribed radius of the top (> 0: a cap closes it), m
  double height = 0.2;       ///< base to top, m
  int pleats = 12;           ///< radial pleats: 2 x pleats generators, >= 2
  int axial_folds = 6;       ///< ring creases between top and base, >= 0
  double pleat_fold_angle = 120 * kDegToRad;  ///< stowed fold of the generators, (0, pi)
  double axial_fold_angle = 150 * kDegToRad;  ///< stowed fold of the rings, (0, pi)
  double hub_fraction = 0.3;  ///< end discs: rigid hub radius over the ring's, (0, 1)
  bool top_disc = true;       ///< a disc closes the top ring (else the top is open)
  bool base_disc = true;      ///< a disc closes the base ring (else the base is open)
  /// Generator 0 a mountain too: pleats + 1 mountains and pleats - 1 valleys among the
  /// generators, the count a flat stack of the wall with thickness needs (its section must
  /// turn once round; docs/folding.md, "Folding with one generator turned"). Maekawa and
  /// Kawasaki hold as for the fan fold; the fan stack and the gathered wall are the fan
  /// fold's and refuse it.
  bool wrap = false;
  /// Stowed by reflection (docs/folding.md, "The cone stowed by reflection"): >= 0, the
  /// share [0, 1) of the gathering (cone_gathered) at which the stowed state sits. Each
  /// interior ring's vertices on the odd generators lie further from the apex by the factor
  /// that makes the ring planar in the wall gathered so far, and every band below a ring is
  /// reflected across that ring's plane (cone_reflected): the wall folded radially and
  /// axially at once, every facet rigid. Creases' kinds and fold angles are that state's.
  /// < 0 (default): the fan fold's rings and kinds. Open ends only, not with `wrap`.
  double reflect_gather = -1;
};

/// Faces of the pattern: band b (0 at the top) of wedge w is face b (2 pleats + 1) + w
/// (wedges 0 and 2 pleats are the half facets at the seam); then the top disc (its hub, then
/// 2 pleats + 1 trapezoids) and the base disc likewise, each only where `top_disc` /
/// `base_disc` asks for it.
int cone_face(const ConeSpec& s, int band, int wedge);

/// Wall vertex on ring `ring` (0 at the top .. axial_folds + 1) and wedge line `line` (0 and
/// 2 pleats + 1: the seam's two sides, 1 .. 2 pleats: generators 0 .. 2 pleats - 1).
int cone_wall_vertex(const ConeSpec& s, int ring, int line);

/// The hub face of the top disc (top = true) or of the base disc; -1 for an open end.
int cone_hub_face(const ConeSpec& s, bool top);

/// The pattern. Throws InputError("<api>", field, ...) for a spec out of range.
CreasePattern cone_crease_pattern(const ConeSpec& s);

/// The wall's flat-folded state (docs/folding.md, "The cone"): every generator at 180 degrees
/// (the facets stacked as a fan about the apex, at the origin, in the x-y plane), then ring r
/// (1 .. axial_folds) folded by `ring_angle` (rad, [0, pi]) of its kind, a Z-fold of the stack
/// about the ring chords, the top band kept in place. Vertices as in `p`, which must be
/// `cone_crease_pattern(s)` with both ends open (throws InputError("<api>", "top_disc" or
/// "base_disc", ...) otherwise). Exact for sheets of no thickness: the layers coincide.
std::vector<Vec3> cone_fan_stack(const ConeSpec& s, const CreasePattern& p, double ring_angle);

/// The open wall gathered part way along its symmetric motion (docs/folding.md, "The
/// gathered cone"): every facet rigid, the even generators' angle to the axis shrunk to
/// (1 - gather) times the deployed one and the odd generators' chosen so that neighbours stay
/// the development's angle apart; azimuths, apex and rings (flat) unchanged. gather = 0 is the
/// deployed cone; gather -> 1 brings the even generators onto the axis. Unlike the fan stack,
/// this is a state a sheet with thickness can take: no two facets coincide. Vertices as in
/// `p` = `cone_crease_pattern(s)` with both ends open; gather in [0, 1) (throws InputError).
std::vector<Vec3> cone_gathered(const ConeSpec& s, const CreasePattern& p, double gather);

/// The stowed state by reflection: the open wall gathered by `s.reflect_gather`
/// (cone_gathered), then, ring by ring from the top, everything below each interior ring
/// reflected across the ring's (horizontal) plane. Isometric with planar facets: the
/// footprint is the gathered wall's, the height its tallest band's. Vertices as in `p` =
/// `cone_crease_pattern(s)`; throws InputError("<api>", "reflect_gather", ...) unless
/// `s.reflect_gather` is in [0, 1).
std::vector<Vec3> cone_reflected(const ConeSpec& s, const CreasePattern& p);

}  // namespace finseg
