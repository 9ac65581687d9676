// The crease pattern of the paper's zigzag strip (generators/zigzag.hpp), for FOLD output, and
// the strip built from it through the pattern path (generators/pattern_sheet.hpp).
#pragma once

#include "generators/pattern_sheet.hpp"
#include "generators/zigzag.hpp"
#include "patterns/crease_pattern.hpp"

namespace finseg {

/// The strip as a FOLD crease pattern: flat along x (0..length) and y (0..width), one quad
/// face per panel, creases M (peak) and V (valley) across it with FOLD fold angles, and the
/// folded coordinates of the generator's initial state (panel 1 rising from the origin).
/// `cells`: each panel cut further by flat (F) edges at the generator's cell boundaries
/// (segments_per_panel cells graded by crease_refinement), one face per cell, panel k's
/// cells being faces k * segments_per_panel .. (k + 1) * segments_per_panel - 1.
CreasePattern zigzag_crease_pattern(const ZigzagSpec& spec, bool cells = false);

/// The pattern-path sheet of the strip: material, crease laws (one law for the peaks, one
/// for the valleys, each for the whole width) and clamps of `spec`, for the pattern
/// zigzag_crease_pattern(spec, true) with one subdivision. Throws InputError when peaks (or
/// valleys) have different laws, or segments_across is not 1.
PatternSheetSpec zigzag_pattern_sheet(const ZigzagSpec& spec);

/// The strip of `spec` built through the pattern path (cells of the generator's layout, plate
/// joints on their shared sides, crease laws on the creases, plate-cell corrections) with the
/// rig of build_zigzag_model (add_zigzag_rig): docs/zigzag.md, "The strip through the
/// pattern path". `crease_bending_in_series`: PatternSheetSpec's (false: the law alone, first
/// order at the creases; kept for comparison).
Model build_zigzag_pattern_model(const ZigzagSpec& spec, bool crease_bending_in_series = true);

}  // namespace finseg
