// Hand-made plates for contact tests: a box body of given mass and size at a pose.
#pragma once

#include <string>

#include "model/model.hpp"

namespace finseg::test {

/// A plate (box body) named `name` of `mass` (kg) and edge lengths `size` (m; z = thickness)
/// with its centroid at `p` (m), turned by `R`, clamped when `fixed`.
inline BodyDef plate(const std::string& name, double mass, const Vec3& size, const Vec3& p,
                     const Mat3& R = Mat3::Identity(), bool fixed = false) {
  BodyDef b;
  b.name = name;
  b.mass = mass;
  b.size = size;
  b.J_B = box_inertia(mass, size);
  b.p0_W = p;
  b.R0_WB = R;
  b.fixed = fixed;
  return b;
}

}  // namespace finseg::test
