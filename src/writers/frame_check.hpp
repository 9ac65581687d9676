// Shared input checks for the animation writers (VTK series, HTML page).
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"
#include "writers/frames.hpp"

namespace finseg {

/// Throws InputError (naming model.source and the offending field) unless every frame has
/// one finite pose per body, box sizes are positive and finite, and times are finite.
void check_frames(const Model& model, const std::vector<Frame>& frames);

/// The eight corners of body `b`'s box in world coordinates (m), in VTK_HEXAHEDRON order:
/// bottom face (-z in B) counter-clockwise seen from +z, then the top face likewise.
std::vector<Vec3> box_corners_W(const Vec3& size, const Vec3& p_W, const Mat3& R_WB);

}  // namespace finseg
