// Narrow phase between two thin plates (segments). Each plate is a rounded plate: its
// mid-surface rectangle (half sizes hx, hy) swept by a sphere of its half thickness r. The
// contact is sampled: a grid of points on the mid-surface of one plate (the source) is
// tested against the rounded plate of the other (the target). A point p lies in contact
// where its distance to the target rectangle is below r_src + r_tgt; the normal points from
// the closest point of the rectangle to p. The distance to a rectangle is continuously
// differentiable outside it, so forces stay smooth while plates slide over edges, meet
// edge to edge or tilt, which the static solver's Newton iteration needs.
//
// Each sample carries a weight (trapezoidal rule over the plate, weights summing to 1) and
// each direction of a pair a share: the smaller plate's points carry the pair, equal plates
// share it half and half, so that a plate lying fully on another feels exactly the IMPACT
// force of eq. 18 at its penetration.
#pragma once

#include <cmath>
#include <vector>

// Eigen/Dense must come before the AutoDiff header that kinematics.hpp pulls in.
#include "core/types.hpp"

#include "elements/kinematics.hpp"

namespace finseg {

/// Shape of a segment: half sizes of the mid-surface rectangle and half thickness.
struct PlateShape {
  double hx = 0, hy = 0, r = 0;
};

inline PlateShape plate_shape(const Vec3& size) {
  return {0.5 * size.x(), 0.5 * size.y(), 0.5 * size.z()};
}

/// One sample point of a plate: position in the body frame (mid-surface) and weight.
struct PlateSample {
  Vec3 r_B = Vec3::Zero();
  double weight = 0;
};

/// n x n grid of samples over the mid-surface rectangle, corners and edges included,
/// trapezoidal weights (sum 1). n >= 2.
std::vector<PlateSample> plate_samples(const PlateShape& s, int n);

/// Shares of the two directions of a pair (points of a on b, points of b on a): the plate
/// of smaller area carries the pair; plates of equal area (within 1e-6) share it.
struct DirectionShares {
  double a_on_b = 0, b_on_a = 0;
};
DirectionShares direction_shares(const PlateShape& a, const PlateShape& b);

/// A sample point of the source plate against the target plate, for scalar T.
template <class T>
struct PointContact {
  Vec3T<T> n_W;  ///< unit normal from the target towards the source point
  Vec3T<T> x_W;  ///< contact point: middle of the overlap of the two rounded surfaces, m
  T depth;       ///< r_src + r_tgt - distance, m (> 0: in contact)
  T height;      ///< signed distance of p_W from the target mid-plane, m
};

/// Contact of the source point p_W (on a plate of half thickness r_src) with the target
/// rounded plate. `side` (+1 / -1) is the face of the target the point is on; it decides
/// the normal only above the rectangle itself, where it keeps a point that has sunk past
/// the target's mid-plane pushing back towards its own side.
template <class T>
PointContact<T> point_on_plate(const BodyKin<T>& tgt, const PlateShape& st, const Vec3T<T>& p_W,
                               double r_src, int side) {
  using std::sqrt;
  const Vec3T<T> ex = tgt.R_WB.col(0), ey = tgt.R_WB.col(1), ez = tgt.R_WB.col(2);
  const Vec3T<T> d = p_W - tgt.p_W;
  const T u = ex.dot(d), v = ey.dot(d), h = ez.dot(d);
  auto outside = [](const T& x, double half) {  // x minus its clamp to [-half, half]
    if (value_of(x) > half) return T(x - T(half));
    if (value_of(x) < -half) return T(x + T(half));
    return T(0);
  };
  const T du = outside(u, st.hx), dv = outside(v, st.hy);
  PointContact<T> c;
  c.height = h;
  T dist;
  if (value_of(du) == 0 && value_of(dv) == 0) {
    dist = T(static_cast<double>(side)) * h;
    c.n_W = T(static_cast<double>(side)) * ez;
  } else {
    dist = sqrt(du * du + dv * dv + h * h);
    c.n_W = (du * ex + dv * ey + h * ez) / dist;
  }
  c.depth = T(r_src + st.r) - dist;
  c.x_W = p_W - c.n_W * ((dist + T(r_src - st.r)) / T(2));
  return c;
}

}  // namespace finseg
