// Small hand-built models of rigid plates for the pressure and chamber tests.
#pragma once

#include <string>

#include "contact_test_util.hpp"

namespace finseg::test {

/// Appends a plate (mid-surface size.x x size.y, thickness size.z) at p_W turned by R_WB;
/// returns its body index.
inline int add_plate(Model& m, const std::string& name, const Vec3& size, const Vec3& p_W,
                     const Mat3& R_WB = Mat3::Identity(), double mass = 0.02, bool fixed = false) {
  m.bodies.push_back(plate(name, mass, size, p_W, R_WB, fixed));
  return static_cast<int>(m.bodies.size()) - 1;
}

}  // namespace finseg::test
