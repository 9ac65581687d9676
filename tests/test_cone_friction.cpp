// The cone stowed by reflection, inflated with friction between its layers (the model of
// examples/cone/reflected_inflate.yaml, 156 cells, mu 0.3 / 0.25).
// With the continuous law (v_s 1e-4, v_d 1e-3 m/s) and two-way gauges, the example as shipped
// until anchor friction: until friction's secant (docs/solvers.md, "Friction's secant") its
// steps fell to 1e-7 s from t = 0.617 s, where layers slide under the strings' pull, and stayed
// there. References: the regularised law tends to Coulomb's as v_s -> 0, so the wall at
// t = 0.66 s must agree with the same run at ten times wider transitions up to the creep that
// allows (v_s t); and the steps must not fall below 5e-7 s (dt_min: the run stops otherwise).
// With the anchor law and slack strings (the example as shipped since): the anchor law tends to
// Coulomb's as k_t -> infinity, a sticking point's spring stretching by at most mu_s F / k_t
// for a face carrying F; so the wall at t = 0.66 s must agree with the same run at a ten times
// softer spring up to that spring's stretch at the scene's reference load (the generator's
// rule: mu_s F_ref / k_t = t / 4 at the scene's k_t), and no step may fall below 5e-7 s; the
// same run without friction must lie farther off than that (else the bound shows nothing).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_test_util.hpp"
#include "scene/scene_reader.hpp"

namespace finseg {
namespace cone_friction_test {

const char* const kScene = "reflected_inflate.yaml";

// The shipped scene with the continuous law and two-way gauges (strings that also push).
std::string continuous_with_gauges() {
  const std::size_t drives =
      read_scene(std::string(FINSEG_SOURCE_DIR) + "/examples/cone/" + kScene).model.drives.size();
  std::string a = " --set contact.friction.model=continuous";
  for (std::size_t i = 0; i < drives; ++i) {
    a += " --set drives." + std::to_string(i) + ".pull_only=false --set drives." +
         std::to_string(i) + ".toe_force=0";
  }
  return a;
}

// The example, copied into `dir` by run_example, run again into `out` with `extra` arguments.
test::CliResult run_again(const test::TempDir& dir, const std::string& out,
                          const std::string& extra) {
  return test::run_finseg(dir, std::string("run ") + kScene + " --out " + out +
                                   " --quiet --set outputs.vtk=false --set outputs.html=false "
                                   "--set outputs.plot=false " +
                                   extra);
}

// RMS distance between the segment centres of two state files (m).
double rms_between(const std::filesystem::path& a_file, const std::filesystem::path& b_file) {
  const std::vector<Vec3> a = test::state_centres(a_file);
  const std::vector<Vec3> b = test::state_centres(b_file);
  EXPECT_EQ(b.size(), a.size());
  double sum = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) sum += (a[i] - b[i]).squaredNorm();
  return std::sqrt(sum / static_cast<double>(a.size()));
}

TEST(ConeFriction, InflationWithLayersSlidingMatchesTheWiderLawToItsCreep) {
  const std::string window =
      "--set solver.t_end=0.66 --set solver.dt_min=5e-7" + continuous_with_gauges();
  test::TempDir dir;
  auto r = test::run_example(dir, "cone", kScene, {"reflected_inflate.fold"}, window);
  ASSERT_EQ(r.code, 0) << r.err;
  const double wide_vs = 1e-3;  // m/s
  r = run_again(dir, "wide",
                window +
                    " --set contact.friction.stiction_speed=1e-3"
                    " --set contact.friction.friction_speed=1e-2");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto summary = nlohmann::json::parse(test::slurp(dir / "run/summary.json"));
  EXPECT_GT(summary["stats"]["secant_solves"].get<long>(), 0);
  ASSERT_EQ(test::state_centres(dir / "run/checkpoint.json").size(), 156u);
  const double rms = rms_between(dir / "run/checkpoint.json", dir / "wide/checkpoint.json");
  RecordProperty("rms_m", std::to_string(rms));
  EXPECT_LT(rms, wide_vs * 0.66);
}

TEST(ConeFriction, AnchorInflationMatchesASofterSpringToItsStickLength) {
  const std::string window = "--set solver.t_end=0.66 --set solver.dt_min=5e-7";
  test::TempDir dir;
  auto r = test::run_example(dir, "cone", kScene, {"reflected_inflate.fold"}, window);
  ASSERT_EQ(r.code, 0) << r.err;
  const Scene scene = read_scene(dir / kScene);
  const ContactDef& c = scene.model.contact;
  ASSERT_EQ(c.friction, FrictionModel::Anchor);
  ASSERT_TRUE(scene.model.drives.front().pull_only);
  const double soft_kt = 0.1 * c.tangential_stiffness;
  r = run_again(dir, "soft",
                window + " --set contact.friction.tangential_stiffness=" + std::to_string(soft_kt));
  ASSERT_EQ(r.code, 0) << r.err;
  // The reference load F_ref of the generator's rule: K (t / 4)^1.5.
  const double quarter = 0.25 * scene.model.bodies.front().thickness;
  const double f_ref = c.stiffness * std::pow(quarter, 1.5);
  const double rms = rms_between(dir / "run/checkpoint.json", dir / "soft/checkpoint.json");
  RecordProperty("rms_m", std::to_string(rms));
  EXPECT_LT(rms, c.mu_static * f_ref / soft_kt);
  // The bound discriminates: without friction the wall lies farther from the run's than that.
  r = run_again(dir, "none", window + " --set contact.friction.model=none");
  ASSERT_EQ(r.code, 0) << r.err;
  const double rms_none = rms_between(dir / "run/checkpoint.json", dir / "none/checkpoint.json");
  RecordProperty("rms_frictionless_m", std::to_string(rms_none));
  EXPECT_GT(rms_none, c.mu_static * f_ref / soft_kt);
}

}  // namespace cone_friction_test
}  // namespace finseg
