// `finseg gen` -> scene file -> read_scene gives the model the generator API builds.
#include <gtest/gtest.h>

#include "cli_test_util.hpp"
#include "generators/cantilever.hpp"
#include "generators/zigzag.hpp"
#include "model_compare.hpp"
#include "scene/scene_reader.hpp"

namespace finseg {
namespace scene_roundtrip_test {

using test::expect_same_model;
using test::run_finseg;
using test::TempDir;

TEST(SceneRoundTrip, GenZigzagReadsBackToTheApiModel) {
  TempDir dir;
  const auto r = run_finseg(dir,
                            "gen zigzag --panels 5 --fold-angle 83 --pattern PVVP "
                            "--segments-per-panel 5 --segments-across 2 --refinement 1.5 "
                            "--fixed-panels 1,5 --pulled-crease 2 --pull-step 0.003 "
                            "--pull-travel 0.05 --gauge-stiffness 2e4 --bending-rigidity 1.3e-5 "
                            "--length 0.4 --width 0.03 --thickness 1.2e-4 --modulus 3.5e9 "
                            "--poisson 0.25 --density 700 --no-contact --out z.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  const Scene scene = read_scene(dir / "z.yaml");
  ZigzagSpec s;
  s.panels = 5;
  s.fold_angle = 83 * kDegToRad;
  s.pattern = "PVVP";
  s.segments_per_panel = 5;
  s.segments_across = 2;
  s.crease_refinement = 1.5;
  s.fixed_panels = {1, 5};
  s.pulled_crease = 2;
  s.pull_step = 0.003;
  s.pull_travel = 0.05;
  s.gauge_stiffness = 2e4;
  s.overrides.bending_rigidity = 1.3e-5;
  s.length = 0.4;
  s.width = 0.03;
  s.thickness = 1.2e-4;
  s.youngs_modulus = 3.5e9;
  s.poisson_ratio = 0.25;
  s.density = 700;
  s.contact = false;
  EXPECT_TRUE(scene.zigzag);
  expect_same_model(build_zigzag_model(s), scene.model);
  EXPECT_EQ(scene.solver.kind, SolverKind::Static);
  EXPECT_TRUE(scene.outputs.plot);  // drive-pulled scenes plot by default
}

TEST(SceneRoundTrip, GenZigzagDefaultsAndGravityOff) {
  TempDir dir;
  const auto r = run_finseg(dir, "gen zigzag --no-gravity --out z.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  ZigzagSpec s;
  s.gravity = false;
  expect_same_model(build_zigzag_model(s), read_scene(dir / "z.yaml").model);
}

TEST(SceneRoundTrip, GenCantileverReadsBackToTheApiModel) {
  TempDir dir;
  const auto r = run_finseg(dir,
                            "gen cantilever --length 0.12 --width 0.03 --thickness 2e-4 "
                            "--modulus 2e9 --poisson 0.2 --density 900 --segments 7 "
                            "--segments-across 3 --tip-force 0.001,0,-0.003 "
                            "--tip-moment 0,1e-5,0 --gravity --solver implicit --t-end 0.5 "
                            "--out c.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  const Scene scene = read_scene(dir / "c.yaml");
  CantileverSpec c;
  c.length = 0.12;
  c.width = 0.03;
  c.thickness = 2e-4;
  c.youngs_modulus = 2e9;
  c.poisson_ratio = 0.2;
  c.density = 900;
  c.segments = 7;
  c.segments_across = 3;
  c.tip_force = Vec3(0.001, 0, -0.003);
  c.tip_moment = Vec3(0, 1e-5, 0);
  c.gravity = true;
  expect_same_model(build_cantilever_model(c), scene.model);
  EXPECT_EQ(scene.solver.kind, SolverKind::Implicit);
  EXPECT_EQ(scene.solver.t_end, 0.5);
  EXPECT_FALSE(scene.outputs.vtk);
}

// A general sheet: one fold with a linear law, a body fixture, a follower load, a drive and
// every probe kind; checked against the quantities the keys describe.
TEST(SceneReader, GeneralSheetSections) {
  const std::string yaml = R"(
material: {youngs_modulus: 3e9, density: 800}
sheet:
  length: 0.2
  width: 0.04
  thickness: 1e-4
  folds:
    - {s: 0.1, angle_deg: 90, law: {type: linear, stiffness: 2e-3, rest_angle_deg: 90}}
discretisation: {segments: 4}
fixtures: {panels: [1], bodies: [seg_r0_s9]}
gravity: [0, 0, -9.81]
loads:
  - {body: seg_r0_s6, point: [0.001, 0, 0], force: [0, 0, 0.01], follower: true}
drives:
  - {name: pull, at: {s: 0.15, y: 0.02}, direction: [0, 0, 2], stiffness: 500, travel: 0.01,
     step: 0.002}
probes:
  - {name: mid, type: point, at: {s: 0.1, y: 0.04}}
  - {name: pull, type: drive, drive: pull}
  - {name: reaction, type: reaction}
  - {name: energy, type: energy}
  - {name: contact, type: contact}
solver: {type: static}
outputs: {vtk: false, html: false, plot: false, phases: false}
)";
  const Scene s = parse_scene(yaml, "inline.yaml");
  const Model& m = s.model;
  ASSERT_EQ(m.creases.size(), 1u);
  EXPECT_DOUBLE_EQ(m.creases[0].initial_fold_angle, kPi / 2);
  // Panel 1 (first panel) and the named body are clamped, nothing else.
  for (const BodyDef& b : m.bodies) EXPECT_EQ(b.fixed, b.panel == 0 || b.name == "seg_r0_s9");
  ASSERT_EQ(m.loads.size(), 1u);
  EXPECT_TRUE(m.loads[0].follower);
  EXPECT_EQ(m.bodies[m.loads[0].body].name, "seg_r0_s6");
  ASSERT_EQ(m.drives.size(), 1u);
  EXPECT_EQ(m.drives[0].direction_W, Vec3(0, 0, 1));
  // Material point (0.15, 0.02): 0.05 m along the second panel, folded by 90 deg about +y
  // at x = 0.1, so it hangs 0.05 m below the crease line.
  EXPECT_NEAR((m.drives[0].start_W - Vec3(0.1, 0.02, -0.05)).norm(), 0, 1e-12);
  ASSERT_EQ(m.probes.size(), 5u);
  EXPECT_EQ(m.probes[1].drives, std::vector<int>{0});
  EXPECT_EQ(m.gravity_W, Vec3(0, 0, -9.81));
  EXPECT_FALSE(s.outputs.phases.enabled);
}

}  // namespace scene_roundtrip_test
}  // namespace finseg
