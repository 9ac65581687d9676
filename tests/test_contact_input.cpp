// The `contact:` scene section: values read as written, every bad value refused with an
// InputError naming the field, and a bad value making the command line exit non-zero.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "collision/contact_laws.hpp"
#include "core/error.hpp"
#include "scene/sections.hpp"

namespace finseg {
namespace contact_input_test {

const char* kGood = R"(
stiffness: 1.2e5
exponent: 1.5
damping_law: flores
restitution: 0.4
damping_depth: 2.0e-5
friction:
  model: anchor
  mu_static: 0.45
  mu_dynamic: 0.35
  stiction_speed: 1.0e-4
  friction_speed: 1.0e-3
  tangential_stiffness: 500
  tangential_damping: 0.01
panel_exclusion: 3
groups: [[1, 2], [2, 3]]
crease_zone: 3.0e-4
initial_overlap: ignore
)";

ContactDef read(const std::string& text) {
  return read_contact_section(YAML::Load(text), {"scene.yaml", "contact"});
}

TEST(ContactInput, ReadsEveryField) {
  const ContactDef c = read(kGood);
  EXPECT_TRUE(c.enabled);
  EXPECT_EQ(c.stiffness, 1.2e5);
  EXPECT_EQ(c.damping_law, ContactDamping::Flores);
  EXPECT_EQ(c.restitution, 0.4);
  EXPECT_EQ(c.damping_depth, 2e-5);
  EXPECT_EQ(c.friction, FrictionModel::Anchor);
  EXPECT_EQ(c.mu_static, 0.45);
  EXPECT_EQ(c.mu_dynamic, 0.35);
  EXPECT_EQ(c.tangential_stiffness, 500);
  EXPECT_EQ(c.panel_exclusion, 3);
  EXPECT_EQ(c.crease_zone, 3e-4);
  EXPECT_EQ(c.initial_overlap, InitialOverlap::Ignore);
  ASSERT_EQ(c.groups.size(), 2u);
  EXPECT_EQ(c.groups[1][1], 2);
}

void expect_refused(const std::string& replace, const std::string& with, const std::string& field) {
  std::string text = kGood;
  const auto at = text.find(replace);
  ASSERT_NE(at, std::string::npos) << replace;
  text.replace(at, replace.size(), with);
  try {
    read(text);
    ADD_FAILURE() << "accepted " << with;
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_EQ(e.file(), "scene.yaml");
  }
}

TEST(ContactInput, RefusesBadValuesNamingTheField) {
  expect_refused("stiffness: 1.2e5", "stiffness: -1", "contact.stiffness");
  expect_refused("exponent: 1.5", "exponent: 0.9", "contact.exponent");
  expect_refused("damping_depth: 2.0e-5", "damping_depth: 0", "contact.damping_depth");
  expect_refused("restitution: 0.4", "restitution: 1.2", "contact.restitution");
  expect_refused("restitution: 0.4", "restitution: 0", "contact.restitution");
  expect_refused("mu_dynamic: 0.35", "mu_dynamic: 0.5", "contact.mu_dynamic");
  expect_refused("stiction_speed: 1.0e-4", "stiction_speed: 0", "contact.stiction_speed");
  expect_refused("friction_speed: 1.0e-3", "friction_speed: 1.0e-5", "contact.friction_speed");
  expect_refused("friction_speed: 1.0e-3", "friction_speed: -1", "contact.friction_speed");
  expect_refused("tangential_stiffness: 500", "tangential_stiffness: 0",
                 "contact.tangential_stiffness");
  expect_refused("panel_exclusion: 3", "panel_exclusion: -1", "contact.panel_exclusion");
  expect_refused("crease_zone: 3.0e-4", "crease_zone: -1e-4", "contact.crease_zone");
  expect_refused("damping_law: flores", "damping_law: soft", "contact.damping_law");
  expect_refused("model: anchor", "model: sticky", "contact.friction.model");
  expect_refused("initial_overlap: ignore", "initial_overlap: keep", "contact.initial_overlap");
  expect_refused("exponent: 1.5", "exponnent: 1.5", "contact.exponnent");
  expect_refused("stiffness: 1.2e5", "stiffness: stiff", "contact.stiffness");
  expect_refused("groups: [[1, 2], [2, 3]]", "groups: [[1, 0]]", "contact.groups[0][1]");
}

TEST(ContactInput, ApiModelsAreCheckedToo) {
  ContactDef c;
  c.enabled = true;
  c.stiffness = 1e5;
  EXPECT_NO_THROW(validate_contact(c, "<api>"));
  c.damping = -1;
  EXPECT_THROW(validate_contact(c, "<api>"), InputError);
  c.damping = 0;
  c.damping_depth = -1;
  EXPECT_THROW(validate_contact(c, "<api>"), InputError);
}

}  // namespace contact_input_test
}  // namespace finseg
