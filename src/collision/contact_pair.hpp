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
  int side = 1;
  const ContactAnchor* anchor = nullptr;
};

/// One touching pair after the narrow phase.
struct PairContact {
  int a = -1, b = -1;
  PlateShape sa, sb;
  std::vector<ActivePoint> points;
};

}  // namespace finseg
