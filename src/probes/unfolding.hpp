// The unfolding probe: which creases open, and in what order. Creases are grouped into lines
// (CreaseDef::line: a FOLD edge cut into several segment sides is one line); every line's
// fold angle is followed from the run's start towards a target, the flat sheet or the angle
// the line has in a named shape of the pattern (e.g. its deployed form; docs/scene.md).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// One crease line an unfolding probe follows.
struct UnfoldingLine {
  std::string name;           ///< "edge17", "seam2" (0-based), or "crease3" (1-based crease)
  std::vector<int> elements;  ///< its crease elements
  double target = 0;          ///< rad: its mean fold angle in the target
  /// Its segment sides on the flat sheet, m (none when the bodies have no flat placement).
  std::vector<std::array<Vec2, 2>> sides_M;
};

/// The model's crease lines in reading order of their names ("edge2" before "edge10"), with
/// their fold angles in shape `shape` (an index into Model::shapes), or 0 (flat) when
/// `shape` < 0.
std::vector<UnfoldingLine> unfolding_lines(const Model& model, int shape);

/// Mean fold angle of each line at a state, rad.
std::vector<double> line_fold_angles(const Model& model, const State& state,
                                     const std::vector<UnfoldingLine>& lines);

/// A line counts as folded (its opening followed) when its target and start angles differ
/// by at least this.
constexpr double kLeastFoldToOpen = 5 * kDegToRad;

/// Share of its way from `start` to `target` that a line at `angle` has come: 0 at its
/// start, 1 at its target (any unit, the same for all three).
double opening_fraction(double angle, double start, double target);

/// An unfolding probe's table has the run's abscissa, the count of lines at least half
/// open, their mean opening, then each line's fold angle in degrees from this column on.
constexpr std::size_t kFirstLineColumn = 3;

/// Column names of an unfolding probe's table (`x` the abscissa's).
std::vector<std::string> unfolding_columns(const std::string& x,
                                           const std::vector<UnfoldingLine>& lines);

/// Row of an unfolding probe's table at abscissa x; `start` holds the lines' angles of the
/// table's first row (deg; empty: this is the first row).
std::vector<double> unfolding_row(double x, const std::vector<double>& angles_rad,
                                  const std::vector<double>& start_deg,
                                  const std::vector<UnfoldingLine>& lines);

/// When and how far one folded line opened over a run.
struct LineOpening {
  std::string name;
  double start_deg = 0, target_deg = 0, final_deg = 0;
  double final_opening = 0;          ///< opening_fraction at the last row
  double half_open_at = NAN;         ///< abscissa where it first came half way (interpolated)
  double open_at = NAN;              ///< abscissa where it first came 90 % of the way
  Vec2 mid_M = Vec2::Constant(NAN);  ///< middle of its sides on the flat sheet, m
};

/// The folded lines in the order they first came half open (those that never did last, the
/// most open first; ties by name order), from the rows of an unfolding probe's table.
std::vector<LineOpening> unfolding_order(const std::vector<std::vector<double>>& rows,
                                         const std::vector<UnfoldingLine>& lines);

}  // namespace finseg
