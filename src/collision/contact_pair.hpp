// A touching pair after the narrow phase: what the contact kernel (collision/contact_forces.cpp)
// and its closed-form Jacobian (collision/contact_jacobian.*) both read.
#pragma once

#include <vector>

#include "collision/narrowphase.hpp"
#include "model/contact_def.hpp"

namespace finseg {

/// One sample point of a pair in contact.
struct ActivePoint {
  int dir = 0;     ///< 0: a sampled on b, 1: b sampled on a
  int sample = 0;  ///< index into the source plate's samples
  Vec3 r_B;        ///< sample in the source body frame, m
  double share = 0;
  int side = 1;         ///< face of the target the point is taken on in this evaluation
  int anchor_side = 1;  ///< the side its history keeps (ContactAnchor::side; 0: none yet)
  const ContactAnchor* anchor = nullptr;
  double overlap = 0;  ///< penetration not pushed against, m (ContactAnchor::overlap)
  /// Past the target's mid-plane (on the far side from `side`) already at the last commit:
  /// beside the polygon it is still pushed back (point_on_plate's `sunk`).
  bool sunk = false;
};

/// Slip speed where the continuous friction law takes its falling branch for this point: its
/// speed at the last accepted step when it has history, else -1 (the current speed).
inline double lag_speed(const ContactDef& def, const ActivePoint& pt) {
  return def.friction == FrictionModel::Continuous && pt.anchor ? pt.anchor->slip_speed : -1;
}

/// One touching pair after the narrow phase.
struct PairContact {
  int a = -1, b = -1;
  PlateShape sa, sb;
  std::vector<ActivePoint> points;
};

/// What the kernel found at one active point (its double evaluation): values for the probes
/// and the history, and the branches it took, which the closed-form Jacobian follows.
struct PointReport {
  Vec3 x_W, n_W, v_t;
  double depth = 0, normal = 0, friction = 0, share = 0, penetration_rate = 0;
  Vec3 f_t = Vec3::Zero();
  double dist = 0, height = 0, du = 0, dv = 0;  ///< point_on_plate's geometry
  PolygonFeature feature;                       ///< point_on_plate's closest feature
  bool spring_capped = false;  ///< anchor friction: the spring (sliding: spring + damper) capped
  bool damper_capped = false;  ///< anchor friction, sticking: the damper capped
};

}  // namespace finseg
