// Exact Jacobian of the contact wrenches (contact_forces.cpp's kernel evaluate_pair) in
// closed form: the chain rule through the narrow phase's geometry, the normal law and the
// friction laws, in 3 x 12 blocks (docs/contact.md, "Jacobian"). The automatic
// differentiation of the kernel stays as the test oracle (ForceJacobian::autodiff).
#pragma once

#include <vector>

#include "collision/contact_laws.hpp"
#include "collision/contact_pair.hpp"
#include "elements/kinematics.hpp"

namespace finseg {

/// Adds the Jacobian of the wrenches of the touching pair `pc` at the bodies' kinematics
/// A (body pc.a) and B (pc.b) to dq, and to dv when `with_velocity`; `reports`: the kernel's
/// double evaluation of the pair, one per point, whose branches it follows. Rows [f_A, tau_A, f_B,
/// tau_B] (world frame, moments about the centroids); columns the pose perturbations [dp_A,
/// dphi_A, dp_B, dphi_B] (dq) or the velocities [v_A, w_A, v_B, w_B] (dv), as in
/// ElementJacobian. `friction`: the continuous law's tangent or its secant (then the blocks
/// are Newton's iteration matrix, not the Jacobian); returns whether a secant differed from
/// its tangent.
bool add_contact_pair_jacobian(const ContactDef& def, const PairContact& pc,
                               const std::vector<PointReport>& reports, const BodyKin<double>& A,
                               const BodyKin<double>& B, bool with_velocity, FrictionSlope friction,
                               Mat12& dq, Mat12& dv);

}  // namespace finseg
