#include "writers/frame_check.hpp"

#include <cmath>

#include "core/error.hpp"

namespace finseg {

void check_frames(const Model& model, const std::vector<Frame>& frames) {
  const std::size_t n = model.bodies.size();
  for (std::size_t b = 0; b < n; ++b) {
    const Vec3& s = model.bodies[b].size;
    if (!s.allFinite() || (s.array() <= 0).any()) {
      throw InputError(model.source, "bodies[" + std::to_string(b) + "].size",
                       "box edge lengths must be finite and > 0 m");
    }
  }
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const Frame& fr = frames[f];
    const std::string where = "frames[" + std::to_string(f) + "]";
    if (fr.p_W.size() != n || fr.R_WB.size() != n) {
      throw InputError(model.source, where + ".p_W/R_WB",
                       "has " + std::to_string(fr.p_W.size()) + "/" +
                           std::to_string(fr.R_WB.size()) + " poses, the model has " +
                           std::to_string(n) + " bodies");
    }
    if (!std::isfinite(fr.t)) throw InputError(model.source, where + ".t", "must be finite");
    for (std::size_t b = 0; b < n; ++b) {
      if (!fr.p_W[b].allFinite() || !fr.R_WB[b].allFinite()) {
        throw InputError(model.source, where + " body " + std::to_string(b),
                         "pose is not finite (NaN or infinity)");
      }
    }
    for (std::size_t c = 0; c < fr.contact_points_W.size(); ++c) {
      if (!fr.contact_points_W[c].allFinite()) {
        throw InputError(model.source, where + ".contact_points_W[" + std::to_string(c) + "]",
                         "must be finite");
      }
    }
  }
}

std::vector<Vec3> box_corners_W(const Vec3& size, const Vec3& p_W, const Mat3& R_WB) {
  const Vec3 h = 0.5 * size;
  static constexpr int kSign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                      {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  std::vector<Vec3> corners(8);
  for (int c = 0; c < 8; ++c) {
    const Vec3 c_B(kSign[c][0] * h.x(), kSign[c][1] * h.y(), kSign[c][2] * h.z());
    corners[c] = p_W + R_WB * c_B;
  }
  return corners;
}

}  // namespace finseg
