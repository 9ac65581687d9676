// The 6-DOF spring-damper force element (paper eqs. 5-7) and its crease variant.
#pragma once

#include <cmath>

#include "elements/crease_law.hpp"
#include "elements/kinematics.hpp"
#include "model/model.hpp"

namespace finseg {

/// Inverse of the left Jacobian of SO(3): maps a left perturbation to d(log R).
template <class T>
Mat3T<T> so3_left_jacobian_inv(const Vec3T<T>& th) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T t2 = th.squaredNorm();
  const Mat3T<T> K = hat(th);
  T c;
  if (t2 < T(1e-8)) {
    c = T(1.0 / 12.0) + t2 / T(720);
  } else {
    const T t = sqrt(t2);
    c = T(1) / t2 - (T(1) + cos(t)) / (T(2) * t * sin(t));
  }
  return Mat3T<T>::Identity() - T(0.5) * K + c * K * K;
}

/// Exact signed rotation (rad) of frame E relative to F about F's y axis, unwrapped next
/// to `previous`: continuous through +-pi and over several turns.
template <class T>
T fold_angle(const Mat3T<T>& R_WE, const Mat3T<T>& R_WF, double previous) {
  using std::atan2;
  const Vec3T<T> uE = R_WE.col(0), uF = R_WF.col(0), a = R_WF.col(1);
  const T raw = atan2(uF.cross(uE).dot(a), uF.dot(uE));
  const double turns = std::round((previous - value_of(raw)) / (2 * kPi));
  return raw + T(2 * kPi * turns);
}

/// Rotation vector theta with exp([theta]x) = R, of all such vectors (log R plus whole turns
/// about its axis) the one nearest to `previous`: continuous where a joint bends through a
/// half turn, |theta| up to 2 pi. previous = 0 gives log R itself.
template <class T>
Vec3T<T> rotation_near(const Mat3T<T>& R, const Vec3& previous) {
  const Vec3T<T> v = so3_log<T>(R);
  const Vec3 v0(value_of(v[0]), value_of(v[1]), value_of(v[2]));
  const double th = v0.norm();
  if (th < 1e-6) return v;  // an axis too short to turn about; previous is near 0 as well
  const double turns = std::round((v0.dot(previous) / th - th) / (2 * kPi));
  if (turns == 0) return v;
  const T norm = v.norm();
  return v * ((norm + T(2 * kPi * turns)) / norm);
}

/// Gradient of the fold angle with respect to a world-frame rotation of the inner body.
template <class T>
Vec3T<T> fold_angle_gradient(const Mat3T<T>& R_WE, const Mat3T<T>& R_WF) {
  const Vec3T<T> uE = R_WE.col(0), uF = R_WF.col(0), a = R_WF.col(1);
  const T x = uF.dot(uE), y = uF.cross(uE).dot(a);
  return (x * uE.cross(a.cross(uF)) - y * uE.cross(uF)) / (x * x + y * y);
}

/// Force element kernel. Forces of the translational springs act on both bodies along one
/// line through P+ (conservative and angular-momentum preserving); the couple derives
/// from U = 1/2 theta^T K theta with theta = log(R_FE), unwrapped through pi against the
/// history (a plate joint bent past a half turn keeps its energy rising). For a crease, the
/// rotation about F's y axis is the exact fold angle and its moment comes from the crease law.
template <class T>
T element_kernel(const ElementDef& e, const CreaseDef* crease, const ElementHistory& hist, double t,
                 const BodyKin<T>& A, const BodyKin<T>& B, Wrench<T>& on_A, Wrench<T>& on_B) {
  const Mat3T<T> R_WE = A.R_WB * e.R_inner_E;
  const Mat3T<T> R_WF = B.R_WB * e.R_outer_F;
  const Vec3T<T> Pp = A.point_W(e.c_inner_B), Pm = B.point_W(e.c_outer_B);
  const Vec3T<T> z_F = R_WF.transpose() * (Pp - Pm) - e.z0_F.cast<T>();
  const Vec3T<T> zdot_F =
      R_WF.transpose() * (A.point_velocity_W(e.c_inner_B) - B.point_velocity_W(e.c_outer_B));
  const Vec3T<T> wrel_F = R_WF.transpose() * (A.w_W - B.w_W);

  Vec3T<T> f_F;
  T energy(0);
  for (int i = 0; i < 3; ++i) {
    f_F[i] = -(e.K[i] * z_F[i] + e.C[i] * zdot_F[i]);
    energy += T(0.5 * e.K[i]) * z_F[i] * z_F[i];
  }
  const Vec3T<T> f_W = R_WF * f_F;
  on_A.add_force_at(f_W, Pp, A.p_W);
  on_B.add_force_at(-f_W, Pp, B.p_W);

  Mat3T<T> R_FE = R_WF.transpose() * R_WE;
  Vec6 K = e.K;
  Vec3T<T> couple_W = Vec3T<T>::Zero();  // on the inner body
  // Crease: U = U_law(phi) + 1/2 th^T K th with phi = s alpha the law's angle
  // (crease_law.hpp: s = +-1) and th = log(R_y(-alpha) R_FE) the rotation left after taking out the
  // fold, expressed in F turned by the fold (K_th2 unused). A world rotation dphi of the inner body
  // moves alpha by grad . dphi and R_y(-alpha) R_FE on the left by R_y(-alpha) R_WF^T dphi - (grad
  // . dphi) e_y, so with g = Jl^-T(th) K th
  //   dU/dphi = (M_alpha - g_y) grad + R_WF R_y(alpha) g,
  // which makes the couple the exact gradient of the energy (symmetric Jacobian).
  Mat3T<T> R_F_fold = Mat3T<T>::Identity();  // F turned by the fold about its y axis
  T M_alpha(0);
  Vec3T<T> grad_alpha = Vec3T<T>::Zero();
  if (crease != nullptr) {
    const double s = law_direction(*crease);
    const T alpha = fold_angle<T>(R_WE, R_WF, hist.fold_angle);
    const double phi = s * value_of(alpha);
    const MomentEnergy law = crease->law->evaluate_with_energy(phi, hist, t);
    const MomentSample& m = law.sample;
    M_alpha = lift(alpha, s * m.moment, m.stiffness);
    energy += lift(alpha, law.energy, s * m.moment);
    grad_alpha = fold_angle_gradient<T>(R_WE, R_WF);
    R_F_fold = so3_exp<T>(Vec3T<T>(T(0), alpha, T(0)));
    R_FE = R_F_fold.transpose() * R_FE;
    K[4] = 0;
  }
  const Vec3T<T> th = rotation_near<T>(R_FE, hist.rotation_F);
  Vec3T<T> Kth;
  for (int i = 0; i < 3; ++i) {
    Kth[i] = K[3 + i] * th[i];
    energy += T(0.5) * Kth[i] * th[i];
  }
  const Vec3T<T> g = so3_left_jacobian_inv<T>(th).transpose() * Kth;
  const Vec3T<T> damp_F(e.C[3] * wrel_F[0], e.C[4] * wrel_F[1], e.C[5] * wrel_F[2]);
  couple_W -= R_WF * (R_F_fold * g + damp_F);
  if (crease != nullptr) couple_W -= (M_alpha - g[1]) * grad_alpha;
  on_A.tau_W += couple_W;
  on_B.tau_W -= couple_W;
  return energy;
}

}  // namespace finseg
