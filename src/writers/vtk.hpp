// VTK output that opens in ParaView: one .vtu (unstructured grid of hexahedra, one per
// segment box) per frame, and a .pvd collection listing them with their times. Arrays are
// binary, zlib-compressed and appended (docs/vtk.md lists them with their units).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "model/state.hpp"
#include "solvers/modes.hpp"
#include "writers/frames.hpp"

namespace finseg {

/// Writes DIR/<stem>_NNNNN.vtu for each frame and DIR/<stem>.pvd (DIR is created if needed).
/// One VTK_HEXAHEDRON per body box, corners in m. Point data: displacement_m (from the
/// model's initial poses), velocity_m_s (when the frame has velocities). Cell data: body,
/// panel, fixed, and when the frame has SegmentFields their arrays (docs/vtk.md).
/// If any frame has contact points, also DIR/<stem>_contacts_NNNNN.vtu (one VTK_VERTEX per
/// point, every frame, possibly empty; point data normal_force_N, penetration_m,
/// friction_force_N when recorded) and DIR/<stem>_contacts.pvd. The .pvd timestep is
/// Frame::t. Files are written atomically (temporary name, then rename). Throws InputError
/// if a frame does not match the model.
void write_vtk_series(const std::string& dir, const std::string& stem, const Model& model,
                      const std::vector<Frame>& frames,
                      const std::function<void(double)>& on_progress = {});

/// One vibration mode: frequency and, per body, the translation and small rotation (world
/// frame) of the shape, scaled so that the largest box-corner displacement is 1.
struct ModeShape {
  double frequency_hz = 0;
  std::vector<Vec3> dp_W, dphi_W;
};

/// Per-body translation and rotation of `mode` about `state`, scaled so that the largest
/// box-corner displacement is 1 (sign: the largest component positive, for determinism).
ModeShape mode_shape(const Model& model, const State& state, const Mode& mode);

/// Writes DIR/<stem>_NNNNN.vtu per mode (N from 1) at the equilibrium `equilibrium`, with the
/// point array mode_shape (dimensionless, for ParaView's Warp By Vector), and DIR/<stem>.pvd
/// whose timestep is the mode number.
void write_vtk_modes(const std::string& dir, const std::string& stem, const Model& model,
                     const Frame& equilibrium, const std::vector<ModeShape>& modes);

}  // namespace finseg
