// Small hand-built models of rigid plates for the pressure and chamber tests.
#pragma once

#include <string>

#include "model/model.hpp"

namespace finseg::test {

/// Adds a plate body (mid-surface size.x x size.y, thickness size.z) at p_W with R_WB.
inline int add_plate(Model& m, const std::string& name, const Vec3& size, const Vec3& p_W,
                     const Mat3& R_WB = Mat3::Identity(), double mass = 0.02, bool fixed = false) {
  BodyDef b;
  b.name = name;
  b.mass = mass;
  b.size = size;
  b.J_B = box_inertia(mass, size);
  b.p0_W = p_W;
  b.R0_WB = R_WB;
  b.fixed = fixed;
  m.bodies.push_back(b);
  return static_cast<int>(m.bodies.size()) - 1;
}

}  // namespace finseg::test
