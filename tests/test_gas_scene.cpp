// The `chambers:` section of scene files (docs/scene.md): read, written back by the scene
// writer and read again to the same chambers, and every bad value refused with file, field
// and range.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "scene/scene_reader.hpp"
#include "scene/scene_writer.hpp"

namespace finseg {
namespace gas_scene_test {

// A flat sheet 0.2 m x 0.1 m in z = 0 (8 segments) under a fixed pyramid roof of four end
// plates, apex 0.05 m above the sheet's centre: a closed chamber of volume L w h / 3.
const char* kStructure = R"(material: {youngs_modulus: 4e9, density: 800}
sheet: {length: 0.2, width: 0.1, thickness: 1e-4}
discretisation: {segments: 4, segments_across: 2}
)";

// Faces and roof of one chamber, indented as a list entry's keys.
const std::string kTent = R"(    faces:
      - {bodies: all, outward: -z}
    end_plates:
      - [[0, 0, 0], [0.2, 0, 0], [0.1, 0.05, 0.05]]
      - [[0.2, 0, 0], [0.2, 0.1, 0], [0.1, 0.05, 0.05]]
      - [[0.2, 0.1, 0], [0, 0.1, 0], [0.1, 0.05, 0.05]]
      - [[0, 0.1, 0], [0, 0, 0], [0.1, 0.05, 0.05]]
)";

const std::string kChambers = "chambers:\n  - name: tent\n" + kTent + R"(    gas: adiabatic
    gas_constant: 296.8
    gamma: 1.4
    temperature: 300
    initial_pressure: 100
    inflow: {at: [0, 0.01, 0.02], mass_flow: [0, 1e-3, 0], temperature: [600, 600, 500]}
    vents:
      - {area: 1e-5, discharge_coefficient: 0.6, ambient_pressure: 0}
      - {area: 2e-5}
  - name: fixed
)" + kTent + R"(    gas: prescribed
    table: {versus: time, at: [0, 1], pressure: [0, 2000]}
)";

void expect_same(const ChamberDef& a, const ChamberDef& b) {
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (std::size_t i = 0; i < a.faces.size(); ++i) {
    EXPECT_EQ(a.faces[i].body, b.faces[i].body);
    EXPECT_EQ(a.faces[i].outward_plus_z, b.faces[i].outward_plus_z);
  }
  EXPECT_EQ(a.end_plates, b.end_plates);
  EXPECT_EQ(a.gas, b.gas);
  EXPECT_EQ(a.prescribed.pressure, b.prescribed.pressure);
  EXPECT_EQ(a.prescribed.at, b.prescribed.at);
  EXPECT_EQ(a.prescribed.pressures, b.prescribed.pressures);
  EXPECT_EQ(a.prescribed.versus, b.prescribed.versus);
  EXPECT_EQ(a.gas_constant, b.gas_constant);
  EXPECT_EQ(a.gamma, b.gamma);
  EXPECT_EQ(a.temperature, b.temperature);
  EXPECT_EQ(a.initial_pressure, b.initial_pressure);
  EXPECT_EQ(a.inflow.at, b.inflow.at);
  EXPECT_EQ(a.inflow.mass_flow, b.inflow.mass_flow);
  EXPECT_EQ(a.inflow.temperature, b.inflow.temperature);
  ASSERT_EQ(a.vents.size(), b.vents.size());
  for (std::size_t v = 0; v < a.vents.size(); ++v) {
    EXPECT_EQ(a.vents[v].area, b.vents[v].area);
    EXPECT_EQ(a.vents[v].discharge_coefficient, b.vents[v].discharge_coefficient);
    EXPECT_EQ(a.vents[v].ambient_pressure, b.vents[v].ambient_pressure);
  }
  EXPECT_EQ(a.initial_volume, b.initial_volume);
}

TEST(GasScene, ReadsChambersAndTheWriterRoundTrips) {
  const Scene s = parse_scene(std::string(kStructure) + kChambers, "g.yaml");
  ASSERT_EQ(s.model.chambers.size(), 2u);
  const ChamberDef& c = s.model.chambers[0];
  EXPECT_EQ(c.name, "tent");
  EXPECT_EQ(c.faces.size(), s.model.bodies.size());
  EXPECT_EQ(c.gas, GasModel::Adiabatic);
  EXPECT_EQ(c.gas_constant, 296.8);
  EXPECT_EQ(c.vents[1].discharge_coefficient, 1.0);  // default
  // The pyramid's volume L w h / 3 (the sheet's segments tile the base).
  EXPECT_NEAR(c.initial_volume / (0.2 * 0.1 * 0.05 / 3), 1.0, 1e-12);
  EXPECT_EQ(s.model.chambers[1].gas, GasModel::Prescribed);
  EXPECT_EQ(s.model.chambers[1].prescribed.pressures[1], 2000);

  const std::string written = chambers_section(s.model);
  const Scene again = parse_scene(std::string(kStructure) + written, "again.yaml");
  ASSERT_EQ(again.model.chambers.size(), 2u) << written;
  for (int i = 0; i < 2; ++i) expect_same(s.model.chambers[i], again.model.chambers[i]);
  EXPECT_EQ(chambers_section(again.model), written);
}

void expect_refused(const std::string& find, const std::string& replace, const std::string& field,
                    const std::string& words) {
  std::string text = std::string(kStructure) + kChambers;
  const auto at = text.find(find);
  ASSERT_NE(at, std::string::npos) << find;
  text.replace(at, find.size(), replace);
  try {
    parse_scene(text, "g.yaml");
    ADD_FAILURE() << "accepted " << replace;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "g.yaml") << e.what();
    // A field ending in '.' or '[' is a prefix: the open place is some face or plate.
    if (field.ends_with('.') || field.ends_with('[')) {
      EXPECT_EQ(e.field().rfind(field, 0), 0u) << e.what();
    } else {
      EXPECT_EQ(e.field(), field) << e.what();
    }
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(GasScene, RefusesBadValuesWithFileFieldAndRange) {
  expect_refused("pressure: [0, 2000]", "pressure: [0, -2000]", "chambers[1].table.pressure[1]",
                 ">= 0 Pa");
  expect_refused("pressure: [0, 2000]", "pressure: [0, .nan]", "chambers[1].table.pressure[1]",
                 ">= 0 Pa");
  expect_refused("initial_pressure: 100", "initial_pressure: -1", "chambers[0].initial_pressure",
                 ">= 0 Pa");
  expect_refused("initial_pressure: 100", "initial_pressure: .nan", "chambers[0].initial_pressure",
                 ">= 0 Pa");
  expect_refused("at: [0, 1]", "at: [1, 0]", "chambers[1].at[1]", "strictly ascending");
  expect_refused("at: [0, 0.01, 0.02]", "at: [0, 0.02, 0.01]", "chambers[0].inflow.at[2]",
                 "strictly ascending");
  expect_refused("mass_flow: [0, 1e-3, 0]", "mass_flow: [0, -1e-3, 0]",
                 "chambers[0].inflow.mass_flow[1]", ">= 0 kg/s");
  expect_refused("temperature: [600, 600, 500]", "temperature: [600, 0, 500]",
                 "chambers[0].inflow.temperature[1]", "> 0 K");
  expect_refused("mass_flow: [0, 1e-3, 0]", "mass_flow: [0, 1e-3]", "chambers[0].inflow.mass_flow",
                 "one per entry");
  expect_refused("gamma: 1.4", "gamma: 1", "chambers[0].gamma", "(1, 3]");
  expect_refused("gas_constant: 296.8", "gas_constant: 0", "chambers[0].gas_constant",
                 "> 0 J/(kg K)");
  expect_refused("temperature: 300", "temperature: -3", "chambers[0].temperature", "> 0 K");
  expect_refused("gas: adiabatic", "gas: hot", "chambers[0].gas",
                 "allowed: prescribed, isothermal, adiabatic");
  expect_refused("{area: 2e-5}", "{area: 0.1}", "chambers[0].vents[1].area",
                 "smaller than the chamber");
  expect_refused("{area: 2e-5}", "{area: -2e-5}", "chambers[0].vents[1].area", "> 0 m^2");
  expect_refused("discharge_coefficient: 0.6", "discharge_coefficient: 1.5",
                 "chambers[0].vents[0].discharge_coefficient", "(0, 1]");
  expect_refused("ambient_pressure: 0", "ambient_pressure: -5",
                 "chambers[0].vents[0].ambient_pressure", ">= 0 Pa");
  expect_refused(
      "outward: -z}\n    end_plates:\n      - [[0, 0, 0], [0.2, 0, 0], [0.1, 0.05, 0.05]]",
      "outward: up}\n    end_plates:\n      - [[0, 0, 0], [0.2, 0, 0], [0.1, 0.05, 0.05]]",
      "chambers[0].faces[0].outward", "allowed: +z, -z");
  expect_refused("gas: prescribed\n", "gas: prescribed\n    vents: []\n", "chambers[1].vents",
                 "not used by gas: prescribed");
  expect_refused("      - [[0, 0.1, 0], [0, 0, 0], [0.1, 0.05, 0.05]]\n    gas: adiabatic",
                 "    gas: adiabatic", "chambers[0].", "open");
  // Inward faces: the sheet's +z side faces the roof.
  expect_refused(
      "outward: -z}\n    end_plates:\n      - [[0, 0, 0], [0.2, 0, 0], [0.1, 0.05, 0.05]]",
      "outward: +z}\n    end_plates:\n      - [[0, 0, 0], [0.2, 0, 0], [0.1, 0.05, 0.05]]",
      "chambers[0].faces[", "open");
  expect_refused("      - [[0, 0, 0], [0.2, 0, 0], [0.1, 0.05, 0.05]]\n      - [[0.2, 0, 0]",
                 "      - [[0, 0, 0], [0.2, 0, 0]]\n      - [[0.2, 0, 0]",
                 "chambers[0].end_plates[0]", "at least 3");
  expect_refused(
      "bodies: all, outward: -z}\n    end_plates:\n      - [[0, 0, 0], [0.2, 0, 0], [0.1, 0.05, "
      "0.05]]",
      "bodies: [nobody], outward: -z}\n    end_plates:\n      - [[0, 0, 0], [0.2, 0, 0], [0.1, "
      "0.05, 0.05]]",
      "chambers[0].faces[0].bodies[0]", "not a body");
}

}  // namespace gas_scene_test
}  // namespace finseg
