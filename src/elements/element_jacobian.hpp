// Exact Jacobian of the force element (bushing.hpp's element_kernel) in closed form, the
// derivation in docs/solvers.md "Closed-form Jacobians". The automatic differentiation of
// the kernel stays as the test oracle (ForceJacobian::autodiff).
#pragma once

#include "elements/bushing.hpp"

namespace finseg {

/// One element's Jacobian blocks. Rows: [f_A, tau_A, f_B, tau_B] (A the inner body, B the
/// outer, world frame, moments about the centroids); columns: the pose perturbations
/// [dp_A, dphi_A, dp_B, dphi_B] (dq) or the velocities [v_A, w_A, v_B, w_B] (dv).
struct ElementJacobian {
  Mat12 dq;
  Mat12 dv;
};

/// Fills J at the bodies' kinematics A, B; dv only when `with_velocity`.
void element_jacobian(const ElementDef& e, const CreaseDef* crease, const ElementHistory& hist,
                      double t, const BodyKin<double>& A, const BodyKin<double>& B,
                      bool with_velocity, ElementJacobian& J);

/// d g / d theta of g = Jl^-T(theta) diag(k) theta, the couple of the rotational springs.
Mat3 rotational_spring_derivative(const Vec3& theta, const Vec3& k);

/// d(grad alpha)/d(dphi_A) of fold_angle_gradient (the inner body's world rotation).
Mat3 fold_gradient_derivative(const Mat3& R_WE, const Mat3& R_WF);

/// Jl^-1(theta), the inverse left Jacobian of SO(3): d log(R) = Jl^-1 (dphi, left increment).
Mat3 left_jacobian_inverse(const Vec3& theta);

/// d (Jl^-T(theta) w) / d theta at fixed w: how the couple of a rotation-vector energy turns
/// with the rotation it is measured on.
Mat3 left_jacobian_inverse_transpose_derivative(const Vec3& theta, const Vec3& w);

}  // namespace finseg
