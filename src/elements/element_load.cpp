#include "elements/element_load.hpp"

#include "elements/bushing.hpp"

namespace finseg {
namespace {

BodyKin<double> kinematics(const State& s, int i) {
  return {s.p_W[i], s.R_WB[i], s.v_W[i], s.w_W[i]};
}

}  // namespace

ElementLoad element_load(const Model& model, const State& state, int k) {
  const ElementDef& e = model.elements[k];
  const CreaseDef* crease = e.crease >= 0 ? &model.creases[e.crease] : nullptr;
  const ElementHistory& h = state.history[k];
  const BodyKin<double> A = kinematics(state, e.inner), B = kinematics(state, e.outer);
  Wrench<double> on_A, on_B;
  element_kernel(e, crease, h, state.t, A, B, on_A, on_B);
  const Mat3 R_WF = B.R_WB * e.R_outer_F;
  const Vec3 Pp = A.point_W(e.c_inner_B);
  ElementLoad out;
  out.force_F = R_WF.transpose() * on_A.f_W;
  // The kernel reports the moment about the inner centroid; move it to P+.
  out.moment_F = R_WF.transpose() * (on_A.tau_W - (Pp - A.p_W).cross(on_A.f_W));
  if (crease == nullptr) return out;
  out.crease = true;
  out.fold_angle = fold_angle<double>(A.R_WB * e.R_inner_E, R_WF, h.fold_angle);
  const double s = law_direction(*crease);
  out.opening_angle = opening_angle(crease_direction(*crease) * out.fold_angle);
  out.crease_moment = s * crease->law->evaluate(s * out.fold_angle, h, state.t).moment;
  return out;
}

std::vector<int> crease_elements(const Model& model, int c) {
  std::vector<int> ks;
  for (std::size_t k = 0; k < model.elements.size(); ++k) {
    if (model.elements[k].crease == c) ks.push_back(static_cast<int>(k));
  }
  return ks;
}

}  // namespace finseg
