#include "writers/frame_check.hpp"

#include <cmath>

#include "core/error.hpp"

namespace finseg {

void check_frames(const Model& model, const std::vector<Frame>& frames) {
  const std::size_t n = model.bodies.size();
  for (std::size_t b = 0; b < n; ++b) {
    const BodyDef& body = model.bodies[b];
    const std::string shape = convexity_problem(body.outline_B, 0);
    if (!shape.empty() || !(body.thickness > 0) || !std::isfinite(body.thickness)) {
      throw InputError(model.source, "bodies[" + std::to_string(b) + "].outline",
                       "must be a convex polygon with a finite thickness > 0 m");
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

}  // namespace finseg
