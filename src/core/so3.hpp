// Rotation-group helpers (exponential and logarithm maps), templated so that the
// element kernels can be evaluated with automatic-differentiation scalars.
#pragma once

#include <cmath>
#include <utility>

#include "core/types.hpp"

namespace finseg {

/// Skew-symmetric matrix [v]x with [v]x u = v x u.
template <class T>
Mat3T<T> hat(const Vec3T<T>& v) {
  Mat3T<T> m;
  m << T(0), -v.z(), v.y(), v.z(), T(0), -v.x(), -v.y(), v.x(), T(0);
  return m;
}

/// sin(t)/t and (1 - cos t)/t^2 at t^2 = th2, by their series near 0.
template <class T>
std::pair<T, T> so3_coefficients(const T& th2) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (th2 < T(1e-12)) return {T(1) - th2 / T(6), T(0.5) - th2 / T(24)};
  const T th = sqrt(th2);
  return {sin(th) / th, (T(1) - cos(th)) / th2};
}

/// Rotation matrix exp([phi]x) (Rodrigues), accurate for small and large angles.
template <class T>
Mat3T<T> so3_exp(const Vec3T<T>& phi) {
  const T th2 = phi.squaredNorm();
  const Mat3T<T> K = hat(phi);
  const auto [a, b] = so3_coefficients(th2);
  return Mat3T<T>::Identity() + a * K + b * K * K;
}

/// Left Jacobian of the exponential map: exp([phi + d]x) = exp([J_l(phi) d]x) exp([phi]x) to
/// first order in d (Barfoot, State Estimation for Robotics, 7.1.3).
template <class T>
Mat3T<T> so3_left_jacobian(const Vec3T<T>& phi) {
  const T th2 = phi.squaredNorm();
  const Mat3T<T> K = hat(phi);
  const auto [a, b] = so3_coefficients(th2);
  const T c = th2 < T(1e-12) ? T(1) / T(6) - th2 / T(120) : (T(1) - a) / th2;  // (t - sin t)/t^3
  return Mat3T<T>::Identity() + b * K + c * K * K;
}

/// Rotation vector phi with exp([phi]x) = R, |phi| <= pi. No singularity except the
/// inherent sign ambiguity at exactly pi.
template <class T>
Vec3T<T> so3_log(const Mat3T<T>& R) {
  using std::atan2;
  using std::sqrt;
  const Vec3T<T> v(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1));  // 2 sin(th) axis
  const T c = (R.trace() - T(1)) / T(2);
  const T s2sq = v.squaredNorm();
  if (c > T(0) && s2sq < T(1e-12)) {
    return (T(0.5) + s2sq / T(48)) * v;  // series of th / (2 sin th); no sqrt at th = 0
  }
  const T s2 = sqrt(s2sq);  // 2 sin(th)
  if (c > T(-0.9)) {
    const T th = atan2(s2 / T(2), c);
    T scale;
    if (th * th < T(1e-10)) {
      scale = T(0.5) + th * th / T(12);  // th / (2 sin th)
    } else {
      scale = th / s2;
    }
    return scale * v;
  }
  // Near pi: the symmetric part carries the axis, the skew part its sign.
  const T th = atan2(s2 / T(2), c);
  const Mat3T<T> B = (R + R.transpose()) / T(2) - c * Mat3T<T>::Identity();  // (1-c) a a^T
  int k = 0;
  if (B(1, 1) > B(k, k)) k = 1;
  if (B(2, 2) > B(k, k)) k = 2;
  Vec3T<T> axis = B.col(k) / sqrt(B(k, k) * (T(1) - c));
  if (axis.dot(v) < T(0)) axis = -axis;
  return th * axis;
}

/// Re-orthonormalises a rotation matrix that has drifted by round-off.
inline Mat3 orthonormalize(const Mat3& R) {
  const Eigen::JacobiSVD<Mat3> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

}  // namespace finseg
