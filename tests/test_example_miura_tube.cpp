// The Z-folded Miura tube (examples/tube/miura_inflate.yaml, issue 13 item 5): the CLI's
// pattern against its construction and Maekawa's theorem, and the shipped scene read and run
// a short while against the adiabatic filling law, so that the example cannot rot.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli_test_util.hpp"
#include "core/error.hpp"
#include "patterns/fold_format.hpp"
#include "patterns/miura_tube_pattern.hpp"
#include "scene/scene_reader.hpp"
#include "solvers/solver.hpp"
#include "test_paths.hpp"

namespace finseg {
namespace example_miura_tube_test {

std::string example(const std::string& file) {
  return std::string(FINSEG_SOURCE_DIR) + "/examples/tube/" + file;
}

// `finseg pattern miura-tube` writes the capped tube: per sheet 2 x N faces, (3 N + 2 (N + 1))
// edges of which the two ridge lines and the two end edges pairs (2 N + 4) are boundaries;
// two rhombic caps of 4 boundary edges. Every interior vertex of a sheet is flat-foldable
// degree 4: Maekawa's theorem, |M - V| = 2. Bad options refused naming the option.
TEST(ExampleMiuraTube, CliWritesTheTubeAndRefusesBadOptions) {
  test::TempDir dir;
  test::CliResult r = test::run_finseg(
      dir,
      "pattern miura-tube --columns 4 --side-a 0.02 --side-b 0.03 --sector-angle 50 "
      "--fold-angle 75 --out m.fold");
  ASSERT_EQ(r.code, 0) << r.err;
  r = test::run_finseg(dir, "pattern check m.fold");
  EXPECT_EQ(r.code, 0) << r.err;
  // Vertices 2 x 3 x 5 + 8 = 38; faces 2 x 8 + 2 = 18; edges 2 x (12 + 10) + 8 = 52, of
  // which 2 x 12 + 8 = 32 boundaries.
  EXPECT_NE(r.out.find("38 vertices, 18 faces, 52 edges (32 B,"), std::string::npos) << r.out;
  const CreasePattern p = read_fold((dir.path() / "m.fold").string(), std::nullopt);
  EXPECT_EQ(p.seams.size(), 2u * 4 + 8);
  const int n = 4;
  for (int sheet : {0, 1}) {
    for (int j = 1; j < n; ++j) {
      const int v = sheet * 3 * (n + 1) + (n + 1) + j;  // (i = 1, j)
      int mountains = 0, valleys = 0;
      for (const PatternEdge& e : p.edges) {
        if (e.vertices[0] != v && e.vertices[1] != v) continue;
        mountains += e.assignment == EdgeAssignment::Mountain;
        valleys += e.assignment == EdgeAssignment::Valley;
      }
      EXPECT_EQ(mountains + valleys, 4) << sheet << " " << j;
      EXPECT_EQ(std::abs(mountains - valleys), 2) << sheet << " " << j;
    }
  }
  for (const char* bad : {"--columns 0", "--side-a 0", "--side-b nan", "--sector-angle 90",
                          "--fold-angle 0", "--fold-angle 90"}) {
    test::expect_refused(dir, std::string("pattern miura-tube ") + bad,
                         "<cli>: " + test::first_word(bad));
  }
}

// The inflation scene, 0.2 ms: its chamber's volume at the start is the stowed tube's closed
// form (2 L H N S at 80 deg), and the gas filled from vacuum by an adiabatic inflator at T_in
// is at T = gamma T_in while the walls have barely moved (the gas work p dV below 1e-2 of
// the injected enthalpy), its mass the ramp's integral mdot_max t^2 / (2 t_ramp).
TEST(ExampleMiuraTube, InflationSceneReadsAndRunsAgainstAdiabaticFilling) {
  Scene scene = read_scene(example("miura_inflate.yaml"));
  ASSERT_EQ(scene.model.chambers.size(), 1u);
  const ChamberDef& c = scene.model.chambers[0];
  MiuraTubeSpec spec;  // the scene's pattern: miura.fold
  spec.columns = 10;
  spec.side_a = 0.02;
  spec.side_b = 0.02;
  spec.sector_angle = 60 * kDegToRad;
  spec.fold_angle = 80 * kDegToRad;
  State s = initial_state(scene.model);
  EXPECT_NEAR(s.chambers[0].volume / miura_tube_volume(spec, spec.fold_angle), 1, 1e-12);
  scene.solver.t_end = 2e-4;
  scene.solver.output_interval = 2e-4;
  const SolverStats st = run_solver(scene.model, s, scene.solver, nullptr);
  ASSERT_EQ(st.status, "ok") << st.message;
  const ChamberGas& g = s.chambers[0];
  const double t = scene.solver.t_end, t_ramp = c.inflow.at[1], mdot = c.inflow.mass_flow[1];
  ASSERT_LT(t, t_ramp);
  EXPECT_NEAR(g.injected, mdot * t * t / (2 * t_ramp), 1e-12 * mdot * t);
  EXPECT_NEAR(g.mass, g.injected - g.vented, 1e-15);
  EXPECT_LT(g.work,
            1e-2 * c.gamma / (c.gamma - 1) * c.gas_constant * c.inflow.temperature[1] * g.injected);
  EXPECT_NEAR(g.temperature / (c.gamma * c.inflow.temperature[1]), 1, 1e-2);
  EXPECT_NEAR(g.pressure, g.mass * c.gas_constant * g.temperature / g.volume, 1e-9 * g.pressure);
}

// The scene key pattern.soft_seams: out-of-range values refused naming the field.
TEST(ExampleMiuraTube, SceneRefusesBadSoftSeams) {
  test::TempDir dir;
  std::ifstream in(example("miura_inflate.yaml"));
  std::stringstream text;
  text << in.rdbuf();
  const std::string good = "scale: 1.0e-2}", scene = text.str();
  ASSERT_NE(scene.find(good), std::string::npos);
  std::filesystem::copy_file(example("miura.fold"), dir.path() / "miura.fold");
  for (const auto& [bad, field] : std::vector<std::pair<std::string, std::string>>{
           {"scale: 0}", "pattern.soft_seams[0].scale"},
           {"scale: 1.5}", "pattern.soft_seams[0].scale"},
           {"scale: 0.1}, {seams: [28], scale: 0.1}", "pattern.soft_seams[1].seams"},
           {"scale: 0.1}, {seams: [20], scale: 0.1}", "pattern.soft_seams[1].seams"}}) {
    std::string changed = scene;
    changed.replace(changed.find(good), good.size(), bad);
    const std::filesystem::path path = dir.path() / "bad.yaml";
    std::ofstream(path) << changed;
    try {
      read_scene(path.string());
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  }
}

}  // namespace example_miura_tube_test
}  // namespace finseg
