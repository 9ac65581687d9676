// `--set key.path=value` (issue 15 item 2): overrides reach the model through the scene's own
// checks, bad paths and values are refused naming them, summary.json records them, and a
// resume with other overrides is refused.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli_test_util.hpp"
#include "core/error.hpp"
#include "scene/scene_reader.hpp"

namespace finseg {
namespace scene_overrides_test {

const char* kScene =
    "material: {youngs_modulus: 4e9, density: 800}\n"
    "sheet: {length: 0.1, width: 0.02, thickness: 1e-4}\n"
    "discretisation: {segments: 4}\n"
    "fixtures: {panels: [1]}\n"
    "loads:\n"
    "  - {at: {s: 0.1, y: 0.01}, force: [0, 0, -1e-3]}\n"
    "solver: {type: static}\n";

Scene with(const std::vector<std::string>& sets) {
  std::vector<Override> o;
  for (const std::string& s : sets) o.push_back(parse_override(s));
  return parse_scene(kScene, "s.yaml", o);
}

// "s.yaml: FIELD: ..." of the InputError that `sets` raise ("" if none).
std::string refusal(const std::vector<std::string>& sets) {
  try {
    with(sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneOverrides, ValuesReachTheModelInOrder) {
  const Scene plain = with({});
  const Scene s = with({"material.youngs_modulus=2e9", "loads.0.force=[0, 0, -2e-3]",
                        "solver.scheme=generalized_alpha", "solver.type=implicit",
                        "discretisation.segments=8", "discretisation.segments=6"});
  EXPECT_EQ(s.model.bodies.size(), plain.model.bodies.size() + 2);  // the last one wins: 6
  EXPECT_EQ(s.model.loads[0].force.z(), -2e-3);
  EXPECT_EQ(s.solver.kind, SolverKind::Implicit);
  EXPECT_EQ(s.solver.scheme, ImplicitScheme::GeneralizedAlpha);
  EXPECT_EQ(s.model.sheet.youngs_modulus, 2e9);
  ASSERT_EQ(s.overrides.size(), 6u);
  EXPECT_EQ(s.overrides[1].path, "loads.0.force");
  EXPECT_EQ(s.overrides[1].value, "[0, 0, -2e-3]");
}

TEST(SceneOverrides, BadPathsAndValuesAreRefusedNamingThem) {
  EXPECT_NE(refusal({"drives.0.speed=1"}).find("s.yaml: drives: no such key"), std::string::npos);
  EXPECT_NE(refusal({"loads.3.force=1"}).find("s.yaml: loads.3: the list has 1 entries"),
            std::string::npos);
  EXPECT_NE(refusal({"sheet.length.x=1"}).find("s.yaml: sheet.length: is a single value"),
            std::string::npos);
  EXPECT_NE(refusal({"solver.tend=1"}).find("s.yaml: solver.tend: unknown key"), std::string::npos);
  EXPECT_NE(refusal({"sheet.thickness=-1"}).find("s.yaml: sheet.thickness:"), std::string::npos);
  EXPECT_NE(refusal({"solver.t_end=[1,"}).find("is not valid YAML"), std::string::npos);
  for (const char* bad : {"solver.t_end", "=1", "solver..t_end=1", "solver.=1"}) {
    EXPECT_THROW(parse_override(bad), InputError) << bad;
  }
}

TEST(SceneOverrides, RunRecordsThemAndResumeNeedsTheSame) {
  const test::TempDir dir;
  test::spit(dir / "s.yaml",
             std::string(kScene) + "outputs: {vtk: false, html: false, plot: false}\n");
  auto r = test::run_finseg(dir,
                            "run s.yaml --out out --quiet --set solver.type=explicit "
                            "--set solver.t_end=2e-3 --set solver.dt=1e-5");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(test::slurp(dir / "out/summary.json"));
  EXPECT_EQ(j.at("overrides"),
            nlohmann::json({"solver.type=explicit", "solver.t_end=2e-3", "solver.dt=1e-5"}));
  EXPECT_EQ(j.at("solver").at("type"), "explicit");
  r = test::run_finseg(dir,
                       "run s.yaml --out out --quiet --resume --set solver.type=explicit "
                       "--set solver.t_end=2e-3 --set solver.dt=1e-5");
  EXPECT_EQ(r.code, 0) << r.err;
  r = test::run_finseg(dir,
                       "run s.yaml --out out --quiet --resume --set solver.type=explicit "
                       "--set solver.t_end=3e-3 --set solver.dt=1e-5");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("scene_hash"), std::string::npos) << r.err;
}

}  // namespace scene_overrides_test
}  // namespace finseg
