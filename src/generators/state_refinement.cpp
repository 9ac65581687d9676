#include "generators/state_refinement.hpp"

#include <limits>
#include <map>
#include <vector>

#include "core/error.hpp"
#include "model/segment_shape.hpp"

namespace finseg {

namespace {

// A segment's centre on the flat sheet, m; refused where it was not cut from a sheet.
const Vec2& flat_centre(const Model& m, const BodyDef& b) {
  if (!b.centroid_M) {
    throw InputError(m.source, "bodies", "a refined state needs segments cut from a sheet");
  }
  return *b.centroid_M;
}

// The coarse segment that carries a fine segment with flat-sheet centre `at` on face `panel`:
// of `face`'s (the coarse segments on that face), the one whose material outline holds `at`,
// else the nearest.
int carrying_body(const Model& coarse, const std::vector<int>& face, int panel, const Vec2& at) {
  if (face.empty()) {
    throw InputError(coarse.source, "bodies",
                     "face " + std::to_string(panel + 1) + " has no segment in the coarse model");
  }
  int best = face.front();
  double nearest = std::numeric_limits<double>::infinity();
  for (const int c : face) {
    const BodyDef& cb = coarse.bodies[static_cast<size_t>(c)];
    if (polygon_contains(material_outline(cb), at, 0)) return c;
    const double d = (*cb.centroid_M - at).norm();
    if (d < nearest) nearest = d, best = c;
  }
  return best;
}

// The segments of each face (BodyDef::panel) cut from a sheet.
std::map<int, std::vector<int>> segments_by_face(const Model& m) {
  std::map<int, std::vector<int>> faces;
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    flat_centre(m, m.bodies[i]);  // refuses a segment without one
    faces[m.bodies[i].panel].push_back(static_cast<int>(i));
  }
  return faces;
}

}  // namespace

State refine_state(const Model& coarse, const State& coarse_state, const Model& fine,
                   double fraction) {
  State s = initial_state(fine);
  std::map<int, std::vector<int>> faces = segments_by_face(coarse);
  for (size_t i = 0; i < fine.bodies.size(); ++i) {
    const BodyDef& b = fine.bodies[i];
    const size_t ci =
        static_cast<size_t>(carrying_body(coarse, faces[b.panel], b.panel, flat_centre(fine, b)));
    const BodyDef& c = coarse.bodies[ci];
    // The carrying body's motion from its start: x -> R_move x + p_move.
    const Mat3 R_move = coarse_state.R_WB[ci] * c.R0_WB.transpose();
    s.R_WB[i] = R_move * b.R0_WB;
    s.p_W[i] = coarse_state.p_W[ci] + R_move * (b.p0_W - c.p0_W);
  }
  for (size_t k = 0; k < fine.elements.size(); ++k) {
    const int crease = fine.elements[k].crease;
    if (crease < 0) continue;
    const double target = fine.creases[static_cast<size_t>(crease)].target_fold_angle;
    if (target != 0) s.history[k].fold_angle = fraction * target;
  }
  return s;
}

}  // namespace finseg
