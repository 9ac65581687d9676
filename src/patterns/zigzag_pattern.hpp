// The crease pattern of the paper's zigzag strip (generators/zigzag.hpp), for FOLD output.
#pragma once

#include "generators/zigzag.hpp"
#include "patterns/crease_pattern.hpp"

namespace finseg {

/// The strip as a FOLD crease pattern: flat along x (0..length) and y (0..width), one quad
/// face per panel, creases M (peak) and V (valley) across it with FOLD fold angles, and the
/// folded coordinates of the generator's initial state (panel 1 rising from the origin).
CreasePattern zigzag_crease_pattern(const ZigzagSpec& spec);

}  // namespace finseg
