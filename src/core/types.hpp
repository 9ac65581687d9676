// Basic linear-algebra types used across finseg. SI units everywhere inside the library.
#pragma once

#include <Eigen/Dense>

namespace finseg {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;

template <class T>
using Vec3T = Eigen::Matrix<T, 3, 1>;
template <class T>
using Mat3T = Eigen::Matrix<T, 3, 3>;

/// z component of the cross product of two flat vectors (> 0: b turns left of a).
inline double cross2d(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegToRad = kPi / 180.0;

}  // namespace finseg
