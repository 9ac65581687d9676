// Body kinematics and wrenches templated on the scalar, so that every element kernel runs
// with double (forces) and with forward-mode autodiff (exact Jacobian blocks).
#pragma once

// Eigen/Dense must come before the AutoDiff module.
#include "core/types.hpp"
// clang-format off
#include <unsupported/Eigen/AutoDiff>
// clang-format on

#include "core/so3.hpp"

namespace finseg {

/// Pose and twist of one body: centroid p_W, orientation R_WB, v_W, w_W.
template <class T>
struct BodyKin {
  Vec3T<T> p_W;
  Mat3T<T> R_WB;
  Vec3T<T> v_W;
  Vec3T<T> w_W;

  Vec3T<T> point_W(const Vec3& r_B) const { return p_W + R_WB * r_B; }
  Vec3T<T> point_velocity_W(const Vec3& r_B) const { return v_W + w_W.cross(Vec3T<T>(R_WB * r_B)); }
};

/// Resultant force and moment about the body centroid, world frame.
template <class T>
struct Wrench {
  Vec3T<T> f_W = Vec3T<T>::Zero();
  Vec3T<T> tau_W = Vec3T<T>::Zero();
  /// Adds force f acting at world point x on a body whose centroid is at c.
  void add_force_at(const Vec3T<T>& f, const Vec3T<T>& x, const Vec3T<T>& c) {
    f_W += f;
    tau_W += (x - c).cross(f);
  }
};

/// Jacobian block of a two-body element: 12 wrench rows by 12 pose or velocity columns.
using Mat12 = Eigen::Matrix<double, 12, 12>;

/// Forward-mode scalar for N perturbation variables.
template <int N>
using AutoDiff = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;

/// Value of an autodiff or plain scalar.
inline double value_of(double x) {
  return x;
}
template <class D>
double value_of(const Eigen::AutoDiffScalar<D>& x) {
  return x.value();
}

/// Lifts a scalar function known by its value f and slope df at value_of(x) to type T.
inline double lift(double /*x*/, double f, double /*df*/) {
  return f;
}
template <class D>
Eigen::AutoDiffScalar<D> lift(const Eigen::AutoDiffScalar<D>& x, double f, double df) {
  return Eigen::AutoDiffScalar<D>(f, df * x.derivatives());
}

}  // namespace finseg
