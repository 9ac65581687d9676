// Shared input checks for the animation writers (VTK series, HTML page).
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"
#include "writers/frames.hpp"

namespace finseg {

/// Throws InputError (naming model.source and the offending field) unless every frame has
/// one finite pose per body, segments are convex polygons with a positive finite thickness,
/// and times are finite.
void check_frames(const Model& model, const std::vector<Frame>& frames);

}  // namespace finseg
