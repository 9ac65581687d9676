// Bad scene files: exit code 2, one line naming the file and the field, no summary.json.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "cli_test_util.hpp"

namespace finseg {
namespace cli_bad_input_test {

using test::run_finseg;
using test::spit;
using test::TempDir;

const char* kCantilever = R"(material:
  youngs_modulus: 4e9
  density: 800
sheet:
  length: 0.1
  width: 0.02
  thickness: 1e-4
discretisation:
  segments: 4
fixtures:
  clamp_start: true
loads:
  - {at: {s: 0.1, y: 0.01}, force: [0, 0, -1e-6]}
probes:
  - {name: tip, type: point, at: {s: 0.1, y: 0.01}}
)";

const char* kZigzag = R"(material: {youngs_modulus: 4e9, density: 800}
sheet: {length: 0.48, width: 0.04, thickness: 1e-4}
discretisation: {segments: 2}
contact: {enabled: false}
zigzag:
  panels: 6
  fold_angle_deg: 80
  pulled_crease: 3
  pull_travel: 0.004
)";

struct BadCase {
  const char* name;
  const char* base;
  const char* find;     // text replaced in the base scene ("" : append)
  const char* replace;  // replacement
  const char* field;    // expected in the message
};

std::string mutate(const BadCase& c) {
  std::string s = c.base;
  if (std::string(c.find).empty()) return s + c.replace;
  const auto at = s.find(c.find);
  EXPECT_NE(at, std::string::npos) << c.name;
  return s.replace(at, std::string(c.find).size(), c.replace);
}

TEST(CliBadInput, GoodBaseScenesRun) {
  for (const char* base : {kCantilever, kZigzag}) {
    TempDir dir;
    spit(dir / "scene.yaml", base);
    const auto r = run_finseg(dir, "run scene.yaml --out out --quiet");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "out/summary.json"));
  }
}

TEST(CliBadInput, TableOfBadScenes) {
  const BadCase cases[] = {
      {"malformed YAML", kCantilever, "segments: 4", "segments: [4", "line"},
      {"unknown key", kCantilever, "density: 800", "density: 800\n  colour: red",
       "material.colour"},
      {"missing field", kCantilever, "  thickness: 1e-4\n", "", "sheet.thickness"},
      {"negative thickness", kCantilever, "thickness: 1e-4", "thickness: -1e-4", "sheet.thickness"},
      {"NaN stiffness", kCantilever, "", "stiffness: {bending_rigidity: .nan}\n",
       "stiffness.bending_rigidity"},
      {"zero density", kCantilever, "density: 800", "density: 0", "material.density"},
      {"wrong type", kCantilever, "segments: 4", "segments: many", "discretisation.segments"},
      {"fixture on a missing body", kCantilever, "clamp_start: true",
       "clamp_start: true\n  bodies: [seg_r0_s99]", "fixtures.bodies[0]"},
      {"probe of a missing drive", kCantilever, "type: point, at: {s: 0.1, y: 0.01}",
       "type: drive, drive: gauge", "probes[0].drive"},
      {"pairs on a point probe", kCantilever, "type: point,", "type: point, pairs: false,",
       "probes[0].pairs: only for type: contact"},
      {"pairs not a flag", kCantilever, "type: point, at: {s: 0.1, y: 0.01}",
       "type: contact, pairs: often", "probes[0].pairs"},
      {"probe named like a pairs file", kCantilever, "  - {name: tip, type: point,",
       "  - {name: tip, type: contact, pairs: true}\n  - {name: tip_pairs, type: point,",
       "probes[1].name"},
      {"load outside the sheet", kCantilever, "{at: {s: 0.1, y: 0.01}", "{at: {s: 0.2, y: 0.01}",
       "loads[0].at.s"},
      {"fold angle 95 deg", kZigzag, "fold_angle_deg: 80", "fold_angle_deg: 95",
       "zigzag.fold_angle_deg"},
      {"pulled crease 9 of 6 panels", kZigzag, "pulled_crease: 3", "pulled_crease: 9",
       "zigzag.pulled_crease"},
      {"clamped panel 7 of 6", kZigzag, "", "fixtures: {panels: [1, 7]}\n", "fixtures.panels"},
      {"unknown solver", kZigzag, "", "solver: {type: magic}\n", "solver.type"},
  };
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.name);
    TempDir dir;
    spit(dir / "bad.yaml", mutate(c));
    const auto r = run_finseg(dir, "run bad.yaml --out out");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("bad.yaml"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.field), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out/summary.json"));
  }
}

// A re-run into the same folder never leaves the earlier run's summary.json standing.
TEST(CliBadInput, DivergedRerunReplacesAnEarlierSummary) {
  TempDir dir;
  spit(dir / "scene.yaml", kCantilever);
  ASSERT_EQ(run_finseg(dir, "run scene.yaml --out out --quiet").code, 0);
  ASSERT_TRUE(std::filesystem::exists(dir / "out/summary.json"));
  std::string diverging = kCantilever;
  diverging += "solver: {type: explicit, t_end: 0.1, dt: 0.01}\n";
  spit(dir / "scene.yaml", diverging);
  const auto r = run_finseg(dir, "run scene.yaml --out out --quiet");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(test::slurp(dir / "out/summary.json").find("\"diverged\""), std::string::npos);
}

TEST(CliBadInput, AFolderGivenForAFileToWriteIsNamed) {
  TempDir dir;
  const auto r = run_finseg(dir, "gen cone --top open --base open --gathered 0.5 --out .");
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_NE(r.err.find("cannot write '.': it is a folder"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "..partial"));
}

}  // namespace cli_bad_input_test
}  // namespace finseg
