// Volume enclosed by oriented segment faces (docs/pressure.md): the divergence theorem
// over the bodies' mid-surface polygons, V = 1/3 sum (c . n) A, exact for a closed
// polyhedron, with its derivative with respect to each body's pose perturbation.
#pragma once

#include <array>
#include <vector>

#include "core/types.hpp"
#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// Corners of a face's mid-surface polygon in its body frame, m, counter-clockwise seen
/// from the outward side.
std::vector<Vec3> face_corners_B(const Model& model, const ChamberFace& face);

/// d V / d(pose perturbation) of one face's body: dp (m^2) and dphi (world-frame rotation
/// vector, m^3/rad), the perturbation compute_forces' Jacobian uses.
struct VolumeGradient {
  int body = -1;
  Vec3 d_dp = Vec3::Zero();
  Vec3 d_dphi = Vec3::Zero();
};

/// Enclosed volume, m^3; positive when the normals point outwards. Exact only when the
/// faces close (check_chamber_closed); otherwise the formula's value for the open set.
double chamber_volume(const Model& model, const State& state,
                      const std::vector<ChamberFace>& faces);

/// Volume and, per face (same order), its derivative with respect to that face's body
/// pose. A body listed twice gets two entries: sum them.
double chamber_volume(const Model& model, const State& state, const std::vector<ChamberFace>& faces,
                      std::vector<VolumeGradient>& gradient);

/// Throws InputError (model.source, `field`) naming a face and the edge where the oriented
/// faces do not close: every edge must be covered by edges of other faces running the
/// opposite way (a consistently oriented closed surface). Tolerance: `rel_tol` times the
/// longest edge. O(edges^2).
void check_chamber_closed(const Model& model, const State& state,
                          const std::vector<ChamberFace>& faces, const std::string& field,
                          double rel_tol = 1e-9);

/// The same for a surface closed by fixed end plates (world polygons, counter-clockwise seen
/// from outside); an open plate edge is named as `field`.end_plates[i] (with a trailing
/// ".faces" of `field` dropped: "chambers[0].faces" -> "chambers[0].end_plates[1]").
void check_chamber_closed(const Model& model, const State& state,
                          const std::vector<ChamberFace>& faces,
                          const std::vector<std::vector<Vec3>>& end_plates,
                          const std::string& field, double rel_tol = 1e-9);

}  // namespace finseg
