// The Z-folded tube (examples/tube, issue 13 item 5): the pattern generator's creases and
// caps, and the shipped scenes read and run a short while, checked against closed forms so
// that the example cannot rot.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "cli_test_util.hpp"
#include "patterns/flat_tube_pattern.hpp"
#include "patterns/pattern_checks.hpp"
#include "patterns/tube_pattern.hpp"
#include "scene/scene_reader.hpp"
#include "solvers/solver.hpp"
#include "test_paths.hpp"

namespace finseg {
namespace example_tube_test {

std::string example(const std::string& file) {
  return std::string(FINSEG_SOURCE_DIR) + "/examples/tube/" + file;
}

// Row line i, facet j of the rolled tube: fold angle (-1)^i alpha cos(phi_j), phi_j the
// facet's centre angle; the caps close the ends (Euler: V - E + F = 2 once rolled).
TEST(ExampleTube, ZFoldCreasesAlternateAndCapsCloseTheTube) {
  const int n = 8, rows = 4;
  const double alpha = 1.2;
  CreasePattern p = zfolded_tube_crease_pattern(n, rows, 0.02, 0.2, alpha);
  validate_pattern(p, "<tube>");
  ASSERT_EQ(p.faces.size(), static_cast<std::size_t>(rows * n + 2));
  int row_creases = 0;
  for (const PatternEdge& e : p.edges) {
    const int u = e.vertices[0], v = e.vertices[1], i = u / (n + 1);
    if (u >= (rows + 1) * (n + 1) || i != v / (n + 1) || i == 0 || i == rows) continue;
    const int j = std::min(u % (n + 1), v % (n + 1));
    const double expected = (i % 2 == 0 ? 1 : -1) * alpha * std::cos(2 * kPi * (j + 0.5) / n);
    EXPECT_NEAR(e.fold_angle, expected, 1e-15) << i << " " << j;
    EXPECT_EQ(e.assignment, expected > 0 ? EdgeAssignment::Valley : EdgeAssignment::Mountain);
    ++row_creases;
  }
  EXPECT_EQ(row_creases, (rows - 1) * n);
  // One seam along the tube per row and one per cap side.
  EXPECT_EQ(p.seams.size(), static_cast<std::size_t>(rows + 2 * n));
  // Rolled, the seams' vertex pairs are one vertex each: V - E + F of the closed surface.
  const int v = static_cast<int>(p.vertices_flat_m.size()) - (rows + 1) - 2 * n;
  const int e = static_cast<int>(p.edges.size() - p.seams.size());
  EXPECT_EQ(v - e + static_cast<int>(p.faces.size()), 2);
}

// `finseg pattern tube` writes the Z-folded tube: its counts from the construction (below);
// bad options refused with exit 2 naming the option.
TEST(ExampleTube, CliWritesTheZFoldedTubeAndRefusesBadOptions) {
  test::TempDir dir;
  test::CliResult r = test::run_finseg(
      dir,
      "pattern tube --facets 8 --rows 4 --radius 0.02 --length 0.2 --fold-angle 60 --out t.fold");
  ASSERT_EQ(r.code, 0) << r.err;
  r = test::run_finseg(dir, "pattern check t.fold");
  EXPECT_EQ(r.code, 0) << r.err;
  // Vertices 5 * 9 + 16 = 61; faces 32 + 2; edges: row lines 5 * 8, strip lines 4 * 9, cap
  // sides 16 = 92; boundary: the two seam columns 8 and the tube's ends 16 and the caps' 16
  // = 40; mountain: 4 * 7 strip creases + 3 * 4 row creases of negative
  // angle (half of each inner row line) = 40; valley 12.
  EXPECT_NE(r.out.find("61 vertices, 34 faces, 92 edges (40 B, 40 M, 12 V)"), std::string::npos)
      << r.out;
  for (const char* bad : {"--facets 2", "--rows 1 --fold-angle 30", "--fold-angle 181",
                          "--radius 0", "--length nan"}) {
    test::expect_refused(dir, std::string("pattern tube ") + bad,
                         "<cli>: " + test::first_word(bad));
  }
}

// The inflation scene from its straight start, 0.4 ms: a rigid-looking chamber filled from
// vacuum by an adiabatic inflator at T_in has T = gamma T_in (the walls have barely moved,
// the gas work p dV is below 1e-3 of the injected enthalpy), its mass the integral of the
// inflator's ramp, m = mdot_max t^2 / (2 t_ramp), and its volume at the start the N-gon
// prism's, N / 2 R^2 sin(2 pi / N) L.
TEST(ExampleTube, InflationSceneReadsAndRunsAgainstAdiabaticFilling) {
  Scene scene = read_scene(example("inflate.yaml"));
  EXPECT_TRUE(read_scene(example("fold.yaml")).folding.has_value());
  ASSERT_EQ(scene.model.chambers.size(), 1u);
  const ChamberDef& c = scene.model.chambers[0];
  const double t_in = c.inflow.temperature[1], mdot = c.inflow.mass_flow[1];
  const double t_ramp = c.inflow.at[1];
  scene.solver.t_end = 4e-4;
  scene.solver.output_interval = 4e-4;
  State s = initial_state(scene.model);
  const int n = 12;
  const double R = 0.025, L = 0.25;
  EXPECT_NEAR(s.chambers[0].volume, n / 2.0 * R * R * std::sin(2 * kPi / n) * L, 1e-15);
  const SolverStats st = run_solver(scene.model, s, scene.solver, nullptr);
  ASSERT_EQ(st.status, "ok") << st.message;
  const ChamberGas& g = s.chambers[0];
  const double t = scene.solver.t_end;
  ASSERT_LT(t, t_ramp);
  EXPECT_NEAR(g.injected, mdot * t * t / (2 * t_ramp), 1e-12 * mdot * t);
  EXPECT_NEAR(g.mass, g.injected - g.vented, 1e-15);
  EXPECT_LT(g.vented, 1e-3 * g.mass);
  EXPECT_LT(g.work, 1e-3 * c.gamma / (c.gamma - 1) * c.gas_constant * t_in * g.injected);
  EXPECT_NEAR(g.temperature / (c.gamma * t_in), 1, 2e-3);
  EXPECT_NEAR(g.pressure, g.mass * c.gas_constant * g.temperature / g.volume, 1e-9 * g.pressure);
}

// `finseg pattern tube --flat GAP` writes the lay-flat tube (counts from the construction,
// below); its options refused with exit 2 naming the option.
TEST(ExampleTube, CliWritesTheLayFlatTubeAndRefusesBadOptions) {
  test::TempDir dir;
  test::CliResult r = test::run_finseg(dir,
                                       "pattern tube --flat 1e-3 --facets 3 --width 0.03 --rows 4 "
                                       "--length 0.1 --seal-length 2e-3 --out f.fold");
  ASSERT_EQ(r.code, 0) << r.err;
  r = test::run_finseg(dir, "pattern check f.fold");
  EXPECT_EQ(r.code, 0) << r.err;
  // N = 2 x 3 + 2 = 8 columns: vertices 5 x 9 + 4 seal middles = 49; faces 2 x 8 straight +
  // 2 x (6 + 6) seal = 40.
  EXPECT_NE(r.out.find("49 vertices, 40 faces"), std::string::npos) << r.out;
  // Each refusal names the option out of range (--flat for the gap itself).
  for (const auto& [bad, option] : std::vector<std::pair<std::string, std::string>>{
           {"--flat 1e-3 --facets 1", "--facets"},
           {"--flat 1e-3 --rows 2", "--rows"},
           {"--flat 0.02 --width 0.04 --facets 4", "--flat"},
           {"--flat -1", "--flat"},
           {"--flat 1e-3 --seal-length 0.3 --length 0.4", "--seal-length"},
           {"--flat 1e-3 --width 0", "--width"},
           {"--flat 1e-3 --radius 0.1", "--radius"},
           {"--flat 1e-3 --fold-angle 30", "--fold-angle"},
           {"--width 0.1", "--width"}}) {
    test::expect_refused(dir, "pattern tube " + bad, "<cli>: " + option);
  }
}

// The lay-flat inflation scene, 0.2 ms: its chamber's volume at the start is the flattened
// tube's closed form (flat_tube_volume), and the gas filled from vacuum by an adiabatic
// inflator at T_in is at T = gamma T_in while the walls have barely moved (as above).
TEST(ExampleTube, LayFlatInflationSceneReadsAndRunsAgainstAdiabaticFilling) {
  Scene scene = read_scene(example("flat_inflate.yaml"));
  ASSERT_EQ(scene.model.chambers.size(), 1u);
  const ChamberDef& c = scene.model.chambers[0];
  FlatTubeSpec spec;  // the scene's pattern: flat.fold
  spec.layer_facets = 4;
  spec.rows = 10;
  spec.width = 0.04;
  spec.gap = 1e-3;
  spec.length = 0.2;
  spec.seal_length = 2e-3;
  State s = initial_state(scene.model);
  EXPECT_NEAR(s.chambers[0].volume / flat_tube_volume(spec), 1, 1e-12);
  scene.solver.t_end = 2e-4;
  scene.solver.output_interval = 2e-4;
  const SolverStats st = run_solver(scene.model, s, scene.solver, nullptr);
  ASSERT_EQ(st.status, "ok") << st.message;
  const ChamberGas& g = s.chambers[0];
  const double t = scene.solver.t_end, t_ramp = c.inflow.at[1], mdot = c.inflow.mass_flow[1];
  ASSERT_LT(t, t_ramp);
  EXPECT_NEAR(g.injected, mdot * t * t / (2 * t_ramp), 1e-12 * mdot * t);
  EXPECT_LT(g.work,
            1e-2 * c.gamma / (c.gamma - 1) * c.gas_constant * c.inflow.temperature[1] * g.injected);
  EXPECT_NEAR(g.temperature / (c.gamma * c.inflow.temperature[1]), 1, 1e-2);
}

}  // namespace example_tube_test
}  // namespace finseg
