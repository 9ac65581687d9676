#include "collision/joint_stops.hpp"

#include <algorithm>
#include <cmath>

#include "collision/contact_laws.hpp"
#include "elements/assembler.hpp"
#include "elements/bushing.hpp"
#include "elements/element_jacobian.hpp"

namespace finseg {
namespace {

// The couple's F components w(theta) = m(|theta|) theta / |theta| and dw/dtheta, with
// m = F(delta) r and delta = (|theta| - pi) r; false where the joint is within a half turn.
bool stop_couple(const ContactDef& c, const Vec3& theta, double r, Vec3& w, Mat3& dw,
                 double& energy) {
  const double angle = theta.norm();
  const double delta = (angle - kPi) * r;
  if (delta <= 0) return false;
  const double force = normal_force<double>(c, delta, 0.0, 0.0);
  const double slope = c.stiffness * c.exponent * std::pow(delta, c.exponent - 1);  // dF/ddelta
  const double m = force * r;
  const Vec3 u = theta / angle;
  w = m * u;
  dw = slope * r * r * u * u.transpose() + (m / angle) * (Mat3::Identity() - u * u.transpose());
  energy = contact_energy(c, delta);  // U = int F r d|theta| = int F d(delta)
  return true;
}

}  // namespace

void add_joint_stops(const Model& model, const State& state, Assembler& as) {
  if (!model.contact.enabled) return;
  for (std::size_t k = 0; k < model.elements.size(); ++k) {
    const Vec3& kept = state.history[k].rotation_F;  // zero unless turned 2 rad or more
    if (kept.isZero()) continue;
    const ElementDef& e = model.elements[k];
    const Mat3 R_WF = state.R_WB[e.outer] * e.R_outer_F;
    const Mat3 R_WE = state.R_WB[e.inner] * e.R_inner_E;
    const Vec3 theta = rotation_near<double>(R_WF.transpose() * R_WE, kept);
    const double r = std::min(e.c_inner_B.norm(), e.c_outer_B.norm());
    Vec3 w;
    Mat3 dw;
    double energy = 0;
    if (!stop_couple(model.contact, theta, r, w, dw, energy)) continue;
    // dE = w . Jl^-1 R_WF^T (dphi_inner - dphi_outer): as a plate cell's side.
    const Mat3 Jl_inv = left_jacobian_inverse(theta);
    const Vec3 g = Jl_inv.transpose() * w;
    const Vec3 tau = -R_WF * g;  // on the inner body
    as.add_energy(energy);
    as.add(e.inner, {Vec3::Zero(), tau});
    as.add(e.outer, {Vec3::Zero(), Vec3(-tau)});
    if (!as.want_jacobian()) continue;
    const Mat3 dg =
        (left_jacobian_inverse_transpose_derivative(theta, w) + Jl_inv.transpose() * dw) * Jl_inv *
        R_WF.transpose();  // by dphi_inner - dphi_outer
    const Mat3 dtau_inner = -R_WF * dg;
    const Mat3 dtau_outer = -dtau_inner + hat(Vec3(R_WF * g));  // R_WF turns with the outer body
    as.add_rotation_block(e.inner, e.inner, dtau_inner);
    as.add_rotation_block(e.inner, e.outer, dtau_outer);
    as.add_rotation_block(e.outer, e.inner, Mat3(-dtau_inner));
    as.add_rotation_block(e.outer, e.outer, Mat3(-dtau_outer));
  }
}

}  // namespace finseg
