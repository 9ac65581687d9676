#include "elements/joint_rotation_history.hpp"

#include <cmath>
#include <vector>

#include "elements/bushing.hpp"

namespace finseg {
namespace {

// Below this turn (rad) log R_FE is the nearest rotation whatever the last one was (a step
// does not turn a joint by pi - 2), so the history keeps zero there and skips the logarithm.
constexpr double kKeptFrom = 2.0;

void commit_joint(const Model& model, State& state, int k) {
  const ElementDef& e = model.elements[k];
  const Mat3 R_FE =
      (state.R_WB[e.outer] * e.R_outer_F).transpose() * (state.R_WB[e.inner] * e.R_inner_E);
  Vec3& theta = state.history[k].rotation_F;
  static const double kKeptTrace = 1 + 2 * std::cos(kKeptFrom);  // trace = 1 + 2 cos(angle)
  if (theta.isZero() && R_FE.trace() > kKeptTrace) return;
  theta = rotation_near<double>(R_FE, theta);
  if (theta.norm() < kKeptFrom) theta.setZero();
}

}  // namespace

void commit_joint_rotations(const Model& model, State& state) {
  // A crease's rotation left after its fold is small; a joint with no rotational stiffness
  // keeps theta = log R_FE (|theta| <= pi), where the unwrapped one could reach 2 pi, the
  // singularity of the left Jacobian, with nothing gained.
  for (int k = 0; k < static_cast<int>(model.elements.size()); ++k) {
    const ElementDef& e = model.elements[k];
    if (e.crease < 0 && e.K.tail<3>().any()) commit_joint(model, state, k);
  }
  // Plate-cell sides without a rotational spring of their own, once each (two cells share one).
  std::vector<char> done(model.elements.size(), 0);
  for (const PlateCellDef& cell : model.plate_cells) {
    for (const PlateCellSide& side : cell.sides) {
      const ElementDef& e = model.elements[side.element];
      if (e.crease >= 0 || e.K.tail<3>().any() || done[side.element]) continue;
      done[side.element] = 1;
      commit_joint(model, state, side.element);
    }
  }
}

}  // namespace finseg
