#include "collision/joint_stops.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "collision/contact_laws.hpp"
#include "elements/assembler.hpp"
#include "elements/bushing.hpp"
#include "elements/element_jacobian.hpp"

namespace finseg {
namespace {

// A crease's fold angle cannot pass pi within one step from below this (rad).
constexpr double kCreaseWatchedFrom = 2.5;

// The stop's moment m = F(delta) r, its slope dm/dangle = F'(delta) r^2 and its energy, at
// delta = (angle - pi) r; false within a half turn.
struct StopMoment {
  double moment = 0, slope = 0, energy = 0;
};
bool stop_moment(const ContactDef& c, double angle, double r, StopMoment& out) {
  const double delta = (angle - kPi) * r;
  if (delta <= 0) return false;
  out.moment = normal_force<double>(c, delta, 0.0, 0.0) * r;
  out.slope = c.stiffness * c.exponent * std::pow(delta, c.exponent - 1) * r * r;
  out.energy = contact_energy(c, delta);  // int F r d(angle) = int F d(delta)
  return true;
}

// Where the stop presses: the shorter segment's centroid, at r from the joint point.
struct Lever {
  double r;
  int body;
};
Lever lever(const ElementDef& e) {
  const double inner = e.c_inner_B.norm(), outer = e.c_outer_B.norm();
  return inner <= outer ? Lever{inner, e.inner} : Lever{outer, e.outer};
}

// The joint's frames at the state: R_WE on the inner body, R_WF on the outer.
struct JointFrames {
  Mat3 R_WE, R_WF;
};
JointFrames frames(const ElementDef& e, const State& state) {
  return {state.R_WB[e.inner] * e.R_inner_E, state.R_WB[e.outer] * e.R_outer_F};
}

// Creases watched from kCreaseWatchedFrom, other joints where the history keeps their rotation
// (2 rad on).
bool watched(const Model& model, const State& state, std::size_t k) {
  if (state.history.size() != model.elements.size()) return false;  // a pose without history
  if (model.elements[k].crease >= 0)
    return std::abs(state.history[k].fold_angle) >= kCreaseWatchedFrom;
  return !state.history[k].rotation_F.isZero();
}

// A joint's unwrapped rotation vector, a crease's unwrapped fold angle.
Vec3 joint_theta(const JointFrames& f, const ElementHistory& h) {
  return rotation_near<double>(f.R_WF.transpose() * f.R_WE, h.rotation_F);
}
double crease_alpha(const JointFrames& f, const ElementHistory& h) {
  return fold_angle<double>(f.R_WE, f.R_WF, h.fold_angle);
}

// The angle a watched element's stop measures: |alpha| of a crease, |theta| of another joint.
double stop_angle(const Model& model, const State& state, std::size_t k) {
  const ElementDef& e = model.elements[k];
  const JointFrames f = frames(e, state);
  if (e.crease >= 0) return std::abs(crease_alpha(f, state.history[k]));
  return joint_theta(f, state.history[k]).norm();
}

// The couple tau on the inner body (-tau on the outer) and the stop's energy; true when the
// Jacobian is wanted.
bool add_couple(Assembler& as, const ElementDef& e, const Vec3& tau, double energy) {
  as.add_energy(energy);
  as.add(e.inner, {Vec3::Zero(), tau});
  as.add(e.outer, {Vec3::Zero(), Vec3(-tau)});
  return as.want_jacobian();
}

// d(couple on the inner body)/d(dphi_inner) and /d(dphi_outer): the outer's rows are minus
// these.
void add_blocks(Assembler& as, const ElementDef& e, const Mat3& d_inner, const Mat3& d_outer) {
  as.add_rotation_block(e.inner, e.inner, d_inner);
  as.add_rotation_block(e.inner, e.outer, d_outer);
  as.add_rotation_block(e.outer, e.inner, Mat3(-d_inner));
  as.add_rotation_block(e.outer, e.outer, Mat3(-d_outer));
}

// A joint's rotation vector theta: U(|theta|), dE = w . Jl^-1 R_WF^T (dphi_inner - dphi_outer)
// with w = m theta / |theta|, as a plate cell's side.
void add_joint_stop(const Model& model, const State& state, int k, Assembler& as) {
  const ElementDef& e = model.elements[k];
  const JointFrames f = frames(e, state);
  const Mat3& R_WF = f.R_WF;
  const Vec3 theta = joint_theta(f, state.history[k]);
  const double angle = theta.norm();
  StopMoment s;
  if (!stop_moment(model.contact, angle, lever(e).r, s)) return;
  const Vec3 u = theta / angle, w = s.moment * u;
  const Mat3 Jl_inv = left_jacobian_inverse(theta);
  const Vec3 g = Jl_inv.transpose() * w;
  if (!add_couple(as, e, -R_WF * g, s.energy)) return;
  const Mat3 dw =
      s.slope * u * u.transpose() + (s.moment / angle) * (Mat3::Identity() - u * u.transpose());
  const Mat3 dg = (left_jacobian_inverse_transpose_derivative(theta, w) + Jl_inv.transpose() * dw) *
                  Jl_inv * R_WF.transpose();  // by dphi_inner - dphi_outer
  const Mat3 d_inner = -R_WF * dg;
  add_blocks(as, e, d_inner, -d_inner + hat(Vec3(R_WF * g)));  // R_WF turns with the outer
}

// A crease's fold angle alpha (unwrapped, ElementHistory::fold_angle): U(|alpha|), the couple
// -U' grad(alpha) on the inner body, as the crease law's (elements/bushing.hpp).
void add_crease_stop(const Model& model, const State& state, int k, Assembler& as) {
  const ElementDef& e = model.elements[k];
  const JointFrames f = frames(e, state);
  const double alpha = crease_alpha(f, state.history[k]);
  StopMoment s;
  if (!stop_moment(model.contact, std::abs(alpha), lever(e).r, s)) return;
  const double sign = alpha > 0 ? 1.0 : -1.0, dU = sign * s.moment;
  const Vec3 grad = fold_angle_gradient<double>(f.R_WE, f.R_WF);
  if (!add_couple(as, e, -dU * grad, s.energy)) return;
  const Mat3 d_inner =
      -s.slope * grad * grad.transpose() - dU * fold_gradient_derivative(f.R_WE, f.R_WF);
  add_blocks(as, e, d_inner, -d_inner + dU * hat(grad));  // grad turns with the outer body
}

}  // namespace

void add_joint_stops(const Model& model, const State& state, Assembler& as) {
  if (!model.contact.enabled) return;
  for (std::size_t k = 0; k < model.elements.size(); ++k) {
    if (!watched(model, state, k)) continue;
    const int i = static_cast<int>(k);
    if (model.elements[k].crease >= 0) {
      add_crease_stop(model, state, i, as);
    } else {
      add_joint_stop(model, state, i, as);
    }
  }
}

std::vector<JointStopReport> joint_stop_reports(const Model& model, const State& state) {
  std::vector<JointStopReport> out;
  if (!model.contact.enabled) return out;
  for (std::size_t k = 0; k < model.elements.size(); ++k) {
    if (!watched(model, state, k)) continue;
    const ElementDef& e = model.elements[k];
    const Lever l = lever(e);
    const double angle = stop_angle(model, state, k);
    StopMoment s;
    if (!stop_moment(model.contact, angle, l.r, s)) continue;
    out.push_back({static_cast<int>(k), e.inner, e.outer, (angle - kPi) * l.r, s.moment / l.r,
                   state.p_W[l.body]});
  }
  return out;
}

}  // namespace finseg
