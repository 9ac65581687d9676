#include "elements/element_jacobian.hpp"

#include <cmath>

namespace finseg {
namespace {

// Column blocks of the 12 perturbation variables.
constexpr int kPA = 0, kPhiA = 3, kPB = 6, kPhiB = 9;

// c(t) of Jl^-1 = I - [th]/2 + c [th]^2 and c'(t) / t. Series below t = 0.3, where the
// closed forms cancel (c'/t subtracts terms of order 1 / t^4).
void left_jacobian_coefficients(double t2, double& c, double& cp_over_t) {
  if (t2 < 0.09) {
    c = 1.0 / 12 + t2 * (1.0 / 720 + t2 * (1.0 / 30240 + t2 / 1209600));
    cp_over_t = 1.0 / 360 + t2 * (1.0 / 7560 + t2 * (1.0 / 201600 + t2 / 5987520));
    return;
  }
  const double t = std::sqrt(t2), cot_half = 1.0 / std::tan(t / 2), s_half = std::sin(t / 2);
  c = 1 / t2 - cot_half / (2 * t);
  cp_over_t = -2 / (t2 * t2) + 1 / (4 * t2 * s_half * s_half) + cot_half / (2 * t2 * t);
}

Mat3 left_jacobian_inv(const Vec3& th, double c) {
  const Mat3 K = hat(th);
  return Mat3::Identity() - 0.5 * K + c * K * K;
}

// Translational springs and dampers: force f on A at P+, -f on B. Written in 3 x 3 blocks
// (the columns of d(P+ - P-) are I, -[r_A], -I, [r_B]).
void add_translational(const ElementDef& e, const BodyKin<double>& A, const BodyKin<double>& B,
                       const Mat3& R_WF, bool with_velocity, ElementJacobian& J) {
  const Vec3 rA = A.R_WB * e.c_inner_B, rB = B.R_WB * e.c_outer_B;
  const Vec3 d = A.p_W + rA - B.p_W - rB;
  const Vec3 u = A.v_W + A.w_W.cross(rA) - B.v_W - B.w_W.cross(rB);
  const Vec3 z_F = R_WF.transpose() * d - e.z0_F, zdot_F = R_WF.transpose() * u;
  const Vec3 Kt = e.K.head<3>(), Ct = e.C.head<3>();
  const Vec3 f = R_WF * -(Kt.cwiseProduct(z_F) + Ct.cwiseProduct(zdot_F));
  const Mat3 S = R_WF * Kt.asDiagonal() * R_WF.transpose();
  const Mat3 hrA = hat(rA), hrB = hat(rB), hf = hat(f), arm_B = hat(Vec3(d + rB));
  const bool damped = Ct.any();
  const Mat3 D = damped ? Mat3(R_WF * Ct.asDiagonal() * R_WF.transpose()) : Mat3::Zero();

  // Force on A: df = -S dp_A + F_phiA dphi_A + S dp_B + F_phiB dphi_B.
  const Mat3 F_phiA = (S + D * hat(A.w_W)) * hrA;
  const Mat3 F_phiB = -(S * (hrB + hat(d)) + D * (hat(B.w_W) * hrB + hat(u)) + hf);
  const Mat3 X = hrA * S, Y = arm_B * S;
  auto& q = J.dq;
  q.block<3, 3>(0, kPA) = -S;
  q.block<3, 3>(0, kPhiA) = F_phiA;
  q.block<3, 3>(0, kPB) = S;
  q.block<3, 3>(0, kPhiB) = F_phiB;
  q.block<3, 3>(3, kPA) = -X;
  q.block<3, 3>(3, kPhiA) = hrA * F_phiA + hf * hrA;
  q.block<3, 3>(3, kPB) = X;
  q.block<3, 3>(3, kPhiB) = hrA * F_phiB;
  q.block<3, 12>(6, 0) = -q.block<3, 12>(0, 0);
  q.block<3, 3>(9, kPA) = hf + Y;
  q.block<3, 3>(9, kPhiA) = -hf * hrA - arm_B * F_phiA;
  q.block<3, 3>(9, kPB) = -hf - Y;
  q.block<3, 3>(9, kPhiB) = -arm_B * F_phiB;
  if (!with_velocity) return;
  auto& v = J.dv;
  const Mat3 DrA = D * hrA, DrB = D * hrB, rAD = hrA * D, bD = arm_B * D;
  v.block<3, 3>(0, kPA) = -D;
  v.block<3, 3>(0, kPhiA) = DrA;
  v.block<3, 3>(0, kPB) = D;
  v.block<3, 3>(0, kPhiB) = -DrB;
  v.block<3, 3>(3, kPA) = -rAD;
  v.block<3, 3>(3, kPhiA) = hrA * DrA;
  v.block<3, 3>(3, kPB) = rAD;
  v.block<3, 3>(3, kPhiB) = -hrA * DrB;
  v.block<3, 12>(6, 0) = -v.block<3, 12>(0, 0);
  v.block<3, 3>(9, kPA) = bD;
  v.block<3, 3>(9, kPhiA) = -arm_B * DrA;
  v.block<3, 3>(9, kPB) = -bD;
  v.block<3, 3>(9, kPhiB) = arm_B * DrB;
}

// Rotational springs and dampers, with the crease law about F's y axis when a crease: the
// couple c = -R_WF (Ry(alpha) g + damp) - (M(alpha) - g_y) grad(alpha) acts on A, -c on B.
// With D = dphi_A - dphi_B, theta moves by Jl^-1 (Ry^T R_WF^T - e_y grad^T) D, alpha by
// grad . D, and R_WF and grad also turn with B.
void add_rotational(const ElementDef& e, const CreaseDef* crease, const ElementHistory& hist,
                    double t, const BodyKin<double>& A, const BodyKin<double>& B, const Mat3& R_WE,
                    const Mat3& R_WF, bool with_velocity, ElementJacobian& J) {
  Mat3 R_FE = R_WF.transpose() * R_WE, Ry = Mat3::Identity(), H_A = Mat3::Zero();
  Vec3 k = e.K.tail<3>(), grad = Vec3::Zero();
  double M = 0, dM = 0;
  if (crease != nullptr) {
    const double s = law_direction(*crease);
    const double alpha = fold_angle<double>(R_WE, R_WF, hist.fold_angle);
    const MomentSample m = crease->law->evaluate(s * alpha, hist, t);
    M = s * m.moment;
    dM = m.stiffness;
    grad = fold_angle_gradient<double>(R_WE, R_WF);
    H_A = fold_gradient_derivative(R_WE, R_WF);
    Ry = so3_exp<double>(Vec3(0, alpha, 0));
    R_FE = Ry.transpose() * R_FE;
    k[1] = 0;
  }
  const Vec3 th = rotation_near<double>(R_FE, hist.rotation_F);
  double c = 0, cp_over_t = 0;
  left_jacobian_coefficients(th.squaredNorm(), c, cp_over_t);
  const Mat3 Jl_inv = left_jacobian_inv(th, c);
  const Vec3 g = Jl_inv.transpose() * k.cwiseProduct(th);
  const Vec3 Cr = e.C.tail<3>();
  const Vec3 w_rel = A.w_W - B.w_W;
  const Vec3 damp = Cr.cwiseProduct(R_WF.transpose() * w_rel);
  const Mat3 Dr = R_WF * Cr.asDiagonal() * R_WF.transpose();
  const Vec3 e_y = Vec3::UnitY();

  const Mat3 P = Ry.transpose() * R_WF.transpose() - e_y * grad.transpose();
  const Mat3 dg = rotational_spring_derivative(th, k) * Jl_inv * P;  // d g / d D
  const double lever = M - g[1];
  const Mat3 R_WFy = R_WF * Ry;
  const Mat3 Jc_D = -R_WFy * dg + R_WF * hat(Vec3(Ry * g)) * e_y * grad.transpose() -
                    grad * (dM * grad.transpose() - dg.row(1)) - lever * H_A;
  const Mat3 Jc_B = -Jc_D + hat(Vec3(R_WF * (Ry * g + damp))) - Dr * hat(w_rel) + lever * hat(grad);
  J.dq.block<3, 3>(3, kPhiA) += Jc_D;
  J.dq.block<3, 3>(3, kPhiB) += Jc_B;
  J.dq.block<3, 3>(9, kPhiA) -= Jc_D;
  J.dq.block<3, 3>(9, kPhiB) -= Jc_B;
  if (!with_velocity) return;
  J.dv.block<3, 3>(3, kPhiA) -= Dr;
  J.dv.block<3, 3>(3, kPhiB) += Dr;
  J.dv.block<3, 3>(9, kPhiA) += Dr;
  J.dv.block<3, 3>(9, kPhiB) -= Dr;
}

}  // namespace

// grad = uE x w / rho^2 with w = x b - y uF, b = a x uF, x = uF . uE, y = b . uE,
// rho^2 = x^2 + y^2; uE turns with A.
Mat3 fold_gradient_derivative(const Mat3& R_WE, const Mat3& R_WF) {
  const Vec3 uE = R_WE.col(0), uF = R_WF.col(0), a = R_WF.col(1);
  const Vec3 b = a.cross(uF);
  const double x = uF.dot(uE), y = b.dot(uE), rho2 = x * x + y * y;
  const Vec3 w = x * b - y * uF, n = uE.cross(w);
  const Mat3 d_duE = (-hat(w) + hat(uE) * (b * uF.transpose() - uF * b.transpose())) / rho2 -
                     (2 / (rho2 * rho2)) * n * (x * uF + y * b).transpose();
  return d_duE * -hat(uE);
}

Mat3 left_jacobian_inverse(const Vec3& th) {
  double c = 0, cp_over_t = 0;
  left_jacobian_coefficients(th.squaredNorm(), c, cp_over_t);
  return left_jacobian_inv(th, c);
}

// Jl^-T w = w + th x w / 2 + c th x (th x w), differentiated at fixed w.
Mat3 left_jacobian_inverse_transpose_derivative(const Vec3& th, const Vec3& w) {
  double c = 0, cp_over_t = 0;
  left_jacobian_coefficients(th.squaredNorm(), c, cp_over_t);
  return -0.5 * hat(w) +
         c * (th.dot(w) * Mat3::Identity() + th * w.transpose() - 2 * w * th.transpose()) +
         cp_over_t * th.cross(th.cross(w)) * th.transpose();
}

// g = Jl^-T v, v = diag(k) theta: Jl^-T diag(k) plus the derivative at fixed v, multiplied
// out (this order of the sums is the one the paper conditions' round-off-sensitive paths were
// measured with).
Mat3 rotational_spring_derivative(const Vec3& th, const Vec3& k) {
  const double t2 = th.squaredNorm();
  double c = 0, cp_over_t = 0;
  left_jacobian_coefficients(t2, c, cp_over_t);
  const Vec3 v = k.cwiseProduct(th);
  const Mat3 Kd = k.asDiagonal();
  const Vec3 th_th_v = th.cross(th.cross(v));
  return Kd + 0.5 * (-hat(v) + hat(th) * Kd) +
         c * (th.dot(v) * Mat3::Identity() + 2 * th * v.transpose() - t2 * Kd -
              2 * v * th.transpose()) +
         cp_over_t * th_th_v * th.transpose();
}

void element_jacobian(const ElementDef& e, const CreaseDef* crease, const ElementHistory& hist,
                      double t, const BodyKin<double>& A, const BodyKin<double>& B,
                      bool with_velocity, ElementJacobian& J) {
  const Mat3 R_WE = A.R_WB * e.R_inner_E, R_WF = B.R_WB * e.R_outer_F;
  add_translational(e, A, B, R_WF, with_velocity, J);
  add_rotational(e, crease, hist, t, A, B, R_WE, R_WF, with_velocity, J);
}

}  // namespace finseg
