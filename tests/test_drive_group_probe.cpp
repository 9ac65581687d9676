// A drive probe over several drives (`drives: [..]`, docs/scene.md): a clamped strip pulled at
// its tip by two gauges of different stiffness, the static solver stepping both alike. The
// group's force is the sum of the single probes' (to the CSV's digits), its pull displacement
// theirs, its point their mean, and in equilibrium the clamp holds the group's force (the
// reaction, a quantity the probe does not compute). Drives that move differently, a name given
// twice or both keys are refused naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "cli_test_util.hpp"

namespace finseg {
namespace drive_group_probe_test {

using test::csv_rows;
using test::run_finseg;
using test::slurp;
using test::spit;
using test::TempDir;

const std::string kStrip = R"(material: {youngs_modulus: 4e9, density: 800}
sheet: {length: 0.1, width: 0.02, thickness: 1e-4}
discretisation: {segments: 8}
fixtures: {clamp_start: true}
drives:
  - {name: a, at: {s: 0.1, y: 0.005}, direction: [0, 0, 1], stiffness: 50, travel: 0.002,
     step: 0.0005}
  - {name: b, at: {s: 0.1, y: 0.015}, direction: [0, 0, 1], stiffness: 80, travel: 0.002,
     step: 0.0005}
solver: {type: static}
outputs: {vtk: false, html: false, plot: false}
probes:
  - {name: pa, type: drive, drive: a}
  - {name: pb, type: drive, drive: b}
)";

std::vector<std::vector<double>> table(const TempDir& dir, const std::string& probe) {
  std::string header;
  return csv_rows(slurp(dir / ("out/" + probe + ".csv")), &header);
}

TEST(DriveGroupProbe, SumsItsGaugesWhichTheClampHolds) {
  TempDir dir;
  spit(dir / "s.yaml", kStrip +
                           "  - {name: both, type: drive, drives: [a, b]}\n"
                           "  - {name: clamp, type: reaction}\n");
  const auto r = run_finseg(dir, "run s.yaml --out out --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto a = table(dir, "pa"), b = table(dir, "pb"), both = table(dir, "both"),
             clamp = table(dir, "clamp");
  ASSERT_EQ(both.size(), a.size());
  ASSERT_EQ(both.size(), clamp.size());
  ASSERT_GE(both.size(), 5u);  // the start and four steps of 0.5 mm
  // pull_displacement_m, force_N, force_x..z_N, point_x..z_m
  for (std::size_t i = 0; i < both.size(); ++i) {
    EXPECT_EQ(both[i][0], a[i][0]);
    for (int c = 1; c <= 4; ++c) {
      EXPECT_NEAR(both[i][c], a[i][c] + b[i][c], 1e-9 * (std::abs(a[i][c]) + std::abs(b[i][c])))
          << i << " " << c;
    }
    for (int c = 5; c <= 7; ++c) {
      EXPECT_NEAR(both[i][c], 0.5 * (a[i][c] + b[i][c]), 1e-12) << i << " " << c;
    }
    // The clamp's reaction on the strip balances the gauges' pull (static equilibrium).
    EXPECT_NEAR(both[i][4], -clamp[i][3], 1e-6 * std::abs(both[i][4]) + 1e-12) << i;
  }
  EXPECT_GT(both.back()[1], 0);  // the gauges pull the strip up: it resists
}

TEST(DriveGroupProbe, DrivesThatMoveDifferentlyOrTwiceAreRefused) {
  for (const auto& [probe, field] :
       {std::pair{"drives: [a, c]", "probes[2].drives: 'c' moves 0.003 m"},
        std::pair{"drives: [a, a]", "probes[2].drives: 'a' is named twice"},
        std::pair{"drives: [a, z]", "probes[2].drives: 'z' is not a drive"},
        std::pair{"drives: []", "probes[2].drives: names no drive"},
        std::pair{"drive: a, drives: [b]", "probes[2].drives: give either"}}) {
    TempDir dir;
    std::string scene = kStrip + "  - {name: both, type: drive, " + probe + "}\n";
    scene.insert(scene.find("solver:"),  // a drive that moves farther than a and b
                 "  - {name: c, at: {s: 0.05, y: 0.01}, direction: [0, 0, 1], stiffness: 10, "
                 "travel: 0.003}\n");
    spit(dir / "bad.yaml", scene);
    const auto r = run_finseg(dir, "run bad.yaml --out out");
    EXPECT_EQ(r.code, 2) << probe;
    EXPECT_NE(r.err.find("bad.yaml"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(field), std::string::npos) << probe << ": " << r.err;
  }
}

}  // namespace drive_group_probe_test
}  // namespace finseg
