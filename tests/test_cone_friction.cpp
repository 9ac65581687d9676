// The cone stowed by reflection, inflated with friction between its layers (the shipped
// examples/cone/reflected_inflate.yaml, mu 0.3 / 0.25 at the law's transition speeds v_s 1e-4,
// v_d 1e-3 m/s). Until friction's secant (docs/solvers.md, "Friction's secant") its steps fell
// to 1e-7 s from t = 0.617 s, where layers slide under the strings' pull, and stayed there.
// References: the regularised law tends to Coulomb's as v_s -> 0, so the wall at t = 0.66 s
// must agree with the same run at ten times wider transitions up to the creep that allows
// (v_s t); and the steps must not fall below 5e-7 s (dt_min: the run stops otherwise).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "cli_test_util.hpp"

namespace finseg {
namespace cone_friction_test {

TEST(ConeFriction, InflationWithLayersSlidingMatchesTheWiderLawToItsCreep) {
  const std::string window = "--set solver.t_end=0.66 --set solver.dt_min=5e-7";
  test::TempDir dir;
  auto r =
      test::run_example(dir, "cone", "reflected_inflate.yaml", {"reflected_inflate.fold"}, window);
  ASSERT_EQ(r.code, 0) << r.err;
  const double wide_vs = 1e-3;  // m/s
  r = test::run_finseg(dir,
                       "run reflected_inflate.yaml --out wide --quiet --set outputs.vtk=false "
                       "--set outputs.html=false --set outputs.plot=false " +
                           window +
                           " --set contact.friction.stiction_speed=1e-3"
                           " --set contact.friction.friction_speed=1e-2");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto summary = nlohmann::json::parse(test::slurp(dir / "run/summary.json"));
  EXPECT_GT(summary["stats"]["secant_solves"].get<long>(), 0);
  const std::vector<Vec3> a = test::state_centres(dir / "run/checkpoint.json");
  const std::vector<Vec3> b = test::state_centres(dir / "wide/checkpoint.json");
  ASSERT_EQ(a.size(), 156u);
  ASSERT_EQ(b.size(), a.size());
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]).squaredNorm();
  const double rms = std::sqrt(sum / static_cast<double>(a.size()));
  RecordProperty("rms_m", std::to_string(rms));
  EXPECT_LT(rms, wide_vs * 0.66);
}

}  // namespace cone_friction_test
}  // namespace finseg
