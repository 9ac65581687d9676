// VTK output that opens in ParaView: one .vtu (unstructured grid of hexahedra, one per
// segment box) per frame, and a .pvd collection listing them with their times.
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"
#include "writers/frames.hpp"

namespace finseg {

/// Writes DIR/<stem>_NNNNN.vtu for each frame and DIR/<stem>.pvd. Cell data: body index,
/// panel, fixed flag. Files are written atomically (temporary name, then rename).
void write_vtk_series(const std::string& dir, const std::string& stem, const Model& model,
                      const std::vector<Frame>& frames);

}  // namespace finseg
