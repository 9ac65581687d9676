// The crease, element and pose probes in scene files: they parse to the crease (1-based in
// the file), element and body named, and every bad reference is refused with the field.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "scene/scene_reader.hpp"

namespace finseg {
namespace probe_kinds_scene_test {

std::string scene_with(const std::string& probe) {
  return R"(
material: {youngs_modulus: 3e9, density: 800}
sheet:
  length: 0.2
  width: 0.04
  thickness: 1e-4
  folds:
    - {s: 0.1, angle_deg: 90, law: {type: linear, stiffness: 2e-3, rest_angle_deg: 90}}
discretisation: {segments: 4}
fixtures: {panels: [1]}
probes:
  - )" + probe +
         "\n";
}

std::string error_of(const std::string& probe) {
  try {
    parse_scene(scene_with(probe), "p.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "<no error>";
}

TEST(ProbeKindsScene, CreaseElementAndPoseProbesParse) {
  const Scene s = parse_scene(scene_with(R"({name: fold, type: crease, crease: 1}
  - {name: joint, type: element, element: crease_r0_s4}
  - {name: tip, type: pose, body: seg_r0_s7})"),
                              "p.yaml");
  const Model& m = s.model;
  ASSERT_EQ(m.probes.size(), 3u);
  EXPECT_EQ(m.probes[0].kind, ProbeKind::Crease);
  EXPECT_EQ(m.probes[0].crease, 0);
  EXPECT_EQ(m.probes[1].kind, ProbeKind::Element);
  ASSERT_GE(m.probes[1].element, 0);
  EXPECT_EQ(m.elements[m.probes[1].element].name, "crease_r0_s4");
  EXPECT_GE(m.elements[m.probes[1].element].crease, 0);
  EXPECT_EQ(m.probes[2].kind, ProbeKind::Pose);
  EXPECT_EQ(m.bodies[m.probes[2].body].name, "seg_r0_s7");
}

TEST(ProbeKindsScene, BadReferencesAreRefusedWithTheirField) {
  EXPECT_NE(error_of("{name: c, type: crease, crease: 2}").find("probes[0].crease"),
            std::string::npos);
  EXPECT_NE(error_of("{name: c, type: crease, crease: 0}").find("probes[0].crease"),
            std::string::npos);
  EXPECT_NE(error_of("{name: c, type: crease}").find("probes[0].crease"), std::string::npos);
  EXPECT_NE(error_of("{name: e, type: element, element: nope}").find("probes[0].element"),
            std::string::npos);
  EXPECT_NE(error_of("{name: p, type: pose, body: nope}").find("probes[0].body"),
            std::string::npos);
  EXPECT_NE(error_of("{name: p, type: pose}").find("probes[0].body"), std::string::npos);
  EXPECT_NE(
      error_of("{name: p, type: point, at: {s: 0.1, y: 0.02}, crease: 1}").find("probes[0].crease"),
      std::string::npos);
}

}  // namespace probe_kinds_scene_test
}  // namespace finseg
