// VTK output that opens in ParaView: one .vtu (unstructured grid of hexahedra, one per
// segment box) per frame, and a .pvd collection listing them with their times.
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"
#include "writers/frames.hpp"

namespace finseg {

/// Writes DIR/<stem>_NNNNN.vtu for each frame and DIR/<stem>.pvd (DIR is created if needed).
/// One VTK_HEXAHEDRON per body box, corners in m; cell data: body index, panel, fixed flag.
/// If any frame has contact points, also DIR/<stem>_contacts_NNNNN.vtu (one VTK_VERTEX per
/// point, every frame, possibly empty) and DIR/<stem>_contacts.pvd. The .pvd timestep is
/// Frame::t. Files are written atomically (temporary name, then rename). Throws InputError
/// if a frame does not match the model.
void write_vtk_series(const std::string& dir, const std::string& stem, const Model& model,
                      const std::vector<Frame>& frames);

}  // namespace finseg
