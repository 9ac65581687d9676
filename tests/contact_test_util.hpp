// Hand-made plates for contact tests: a box body of given mass and size at a pose.
#pragma once

#include <string>

#include "collision/contact_laws.hpp"
#include "model/model.hpp"

namespace finseg::test {

/// A plate (box body) named `name` of `mass` (kg) and edge lengths `size` (m; z = thickness)
/// with its centroid at `p` (m), turned by `R`, clamped when `fixed`.
inline BodyDef plate(const std::string& name, double mass, const Vec3& size, const Vec3& p,
                     const Mat3& R = Mat3::Identity(), bool fixed = false) {
  BodyDef b;
  b.name = name;
  set_box(b, size, mass);
  b.p0_W = p;
  b.R0_WB = R;
  b.fixed = fixed;
  return b;
}

/// Contact switched on with the suggested normal values and continuous (Adams) friction of
/// coefficients mu_s, mu_d (the default transition speeds).
inline ContactDef continuous_contact(const ContactSuggestion& sug, double mu_s, double mu_d) {
  ContactDef c;
  c.enabled = true;
  c.stiffness = sug.stiffness;
  c.damping = sug.damping;
  c.damping_depth = sug.damping_depth;
  c.friction = FrictionModel::Continuous;
  c.mu_static = mu_s;
  c.mu_dynamic = mu_d;
  return c;
}

/// Contact switched on with the suggested normal and tangential values and elastic-anchor
/// friction of coefficients mu_s, mu_d.
inline ContactDef anchor_contact(const ContactSuggestion& sug, double mu_s, double mu_d) {
  ContactDef c = continuous_contact(sug, mu_s, mu_d);
  c.friction = FrictionModel::Anchor;
  c.tangential_stiffness = sug.tangential_stiffness;
  c.tangential_damping = sug.tangential_damping;
  return c;
}

}  // namespace finseg::test
