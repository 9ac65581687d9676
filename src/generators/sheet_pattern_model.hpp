// A sheet of the sheet generator built through the pattern path (docs/stiffness.md, "Sheets
// from crease patterns"): its cells the pattern's faces, plate joints and cell corrections on
// their sides, each fold's law on its crease sides. What build_sheet_model builds for a sheet
// of more than one row, and the zigzag strip's pattern path (docs/zigzag.md).
#pragma once

#include "generators/pattern_sheet.hpp"
#include "generators/sheet.hpp"
#include "patterns/sheet_pattern.hpp"

namespace finseg {

/// `spec` built through the pattern path: its pattern sheet_crease_pattern(spec, true), one
/// face a cell, each fold's law on its crease sides (for the whole width), the clamp column
/// and the fixed panels' faces fixed; bodies' `panel` the sheet's panels (between folds),
/// `Model::sheet` the sheet's own extent (the clamp column lies before x = 0). Throws
/// InputError for stiffness overrides other than the bending rigidity EI (a plate rigidity D =
/// EI / (width (1 - nu^2)), free long sides). `crease_bending_in_series`: PatternSheetSpec's.
Model build_sheet_pattern_model(const SheetSpec& spec, bool crease_bending_in_series = true);

}  // namespace finseg
