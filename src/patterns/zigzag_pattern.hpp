// The crease pattern of the paper's zigzag strip (generators/zigzag.hpp), for FOLD output, and
// the strip built from it through the pattern path (generators/sheet_pattern_model.hpp).
#pragma once

#include "generators/zigzag.hpp"
#include "patterns/crease_pattern.hpp"

namespace finseg {

/// The strip as a FOLD crease pattern (sheet_crease_pattern of zigzag_sheet(spec)): flat along
/// x (0..length) and y (0..width), one quad face per panel, creases M (peak) and V (valley)
/// across it with FOLD fold angles, and the folded coordinates of the generator's initial
/// state (panel 1 rising from the origin). `cells`: each panel cut further by flat (F) edges
/// at the generator's cell boundaries (segments_per_panel cells graded by
/// crease_refinement) and into segments_across rows, one face per cell.
CreasePattern zigzag_crease_pattern(const ZigzagSpec& spec, bool cells = false);

/// The strip of `spec` built through the pattern path (build_sheet_pattern_model: cells of the
/// generator's layout, plate joints on their shared sides, each crease's law on its sides,
/// plate-cell corrections) with the rig of build_zigzag_model (add_zigzag_rig): docs/zigzag.md,
/// "The strip through the pattern path". `crease_bending_in_series`: PatternSheetSpec's (false:
/// the law alone, first order at the creases; kept for comparison).
Model build_zigzag_pattern_model(const ZigzagSpec& spec, bool crease_bending_in_series = true);

}  // namespace finseg
