// The rectangular sheet of the sheet generator (generators/sheet.hpp) as a crease pattern:
// what a sheet cut into more than one row is built from (the pattern path's plate joints and
// cell corrections, docs/stiffness.md), and the FOLD form of the zigzag strip.
#pragma once

#include <vector>

#include "generators/sheet.hpp"
#include "patterns/crease_pattern.hpp"

namespace finseg {

/// A sheet's pattern and what each of its faces and creases stands for.
struct SheetPattern {
  CreasePattern pattern;
  std::vector<int> face_panel;               ///< panel (0-based, between folds) of each face
  std::vector<bool> face_clamp;              ///< faces of the clamp column (SheetSpec::clamp_start)
  std::vector<std::vector<int>> fold_edges;  ///< pattern edges (0-based) on each fold line
};

/// The flat sheet x in [0, length], y in [0, width] cut across its length at the folds
/// (M for a peak, V for a valley, FOLD fold angles) and, with `cells`, at the generator's cell
/// boundaries (panel_cell_bounds; F edges) and along it into `cells_across` rows (F edges);
/// one face per cell, column by column (face j rows + r). Its folded coordinates are the
/// generator's initial state. With `spec.clamp_start` a column of clamp faces lies before
/// the sheet, x in [-h/2, 0] for a first cell of length h: the sheet is clamped along its
/// side x = 0 (the generator's fixed half cell). Vertex (line j, row boundary r) is
/// j (rows + 1) + r.
SheetPattern sheet_crease_pattern(const SheetSpec& spec, bool cells);

}  // namespace finseg
