// The deployment peak (probes/deployment_peak.hpp): a hump followed by the taut rise at the
// end of the travel, curves without a peak, the window, and the zigzag's deployed travel
// against its closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "generators/zigzag.hpp"
#include "probes/deployment_peak.hpp"
#include "writers/run_outputs.hpp"

namespace finseg {
namespace deployment_peak_test {

// Hump of 0.14 N at 26 mm, then the strip pulled taut: a rise to 0.256 N at 141.8 mm, the
// shape of condition 1's gauge curve.
double hump_then_taut(double x) {
  const double hump = 0.14 * std::exp(-std::pow((x - 0.026) / 0.012, 2));
  return hump + 0.256 * std::pow(x / 0.1418, 12);
}

std::vector<double> grid(double a, double b, int n) {
  std::vector<double> x;
  for (int i = 0; i < n; ++i) x.push_back(a + (b - a) * i / (n - 1));
  return x;
}

std::vector<double> apply(const std::vector<double>& x, double (*f)(double)) {
  std::vector<double> y;
  for (double xi : x) y.push_back(f(xi));
  return y;
}

TEST(DeploymentPeak, HumpThenTautRiseGivesTheHumpNotTheEnd) {
  const std::vector<double> x = grid(0, 0.1418, 710);  // 0.2 mm steps: 26 mm is a sample
  const std::vector<double> f = apply(x, hump_then_taut);
  const DeploymentPeak p = find_deployment_peak(x, f, -INFINITY, INFINITY);
  ASSERT_TRUE(p.found);
  // The taut term adds 0.256 (26/141.8)^12 = 3e-10 N and moves the maximum by < 1e-9 m.
  EXPECT_NEAR(p.x, 0.026, 1e-6);
  EXPECT_NEAR(p.force, 0.14, 1e-8);
  // The largest force over the travel is the end of the taut rise.
  const int m = max_force_index(x, f, -INFINITY, INFINITY);
  EXPECT_EQ(m, static_cast<int>(x.size()) - 1);
  EXPECT_NEAR(f[m], 0.256, 1e-12);  // the hump's tail there is exp(-93) of 0.14 N
}

TEST(DeploymentPeak, NoPeakWhenTheForceOnlyRisesOrWigglesLessThanTheDrop) {
  const std::vector<double> x = grid(0, 0.1, 101);
  std::vector<double> rising;
  for (double xi : x) rising.push_back(xi * xi);
  EXPECT_FALSE(find_deployment_peak(x, rising, -INFINITY, INFINITY).found);
  // A dip of 2 % of the range after x = 50 mm is below the 5 % drop: not a peak.
  std::vector<double> wiggle = rising;
  for (std::size_t i = 51; i < 55; ++i) wiggle[i] = rising[50] - 0.02 * rising.back();
  EXPECT_FALSE(find_deployment_peak(x, wiggle, -INFINITY, INFINITY).found);
  // A dip of 10 % makes the sample before it a peak.
  for (std::size_t i = 51; i < 55; ++i) wiggle[i] = rising[50] - 0.10 * rising.back();
  const DeploymentPeak p = find_deployment_peak(x, wiggle, -INFINITY, INFINITY);
  ASSERT_TRUE(p.found);
  EXPECT_EQ(p.index, 50);
}

TEST(DeploymentPeak, WindowEndsTheSearchAndAFallMustHappenInside) {
  // Two humps, 0.1 N at 20 mm and 0.3 N at 80 mm.
  const std::vector<double> x = grid(0, 0.1, 501);
  std::vector<double> f;
  for (double xi : x) {
    f.push_back(0.1 * std::exp(-std::pow((xi - 0.02) / 0.005, 2)) +
                0.3 * std::exp(-std::pow((xi - 0.08) / 0.005, 2)));
  }
  EXPECT_NEAR(find_deployment_peak(x, f, -INFINITY, INFINITY).x, 0.08, 1e-9);
  // Deployed at 60 mm: the second hump is past the end of deployment.
  const DeploymentPeak early = find_deployment_peak(x, f, -INFINITY, 0.06);
  EXPECT_NEAR(early.x, 0.02, 1e-9);
  EXPECT_NEAR(early.force, 0.1, 1e-9);
  // Window ending on the rising flank of the second hump: still rising, so not a peak.
  EXPECT_NEAR(find_deployment_peak(x, f, -INFINITY, 0.079).x, 0.02, 1e-9);
}

TEST(DeploymentPeak, ZigzagDeployedTravelIsTheStraightLinkageLift) {
  // Closed form: panels (2)-(3) straight between the fixed crease 1 and the pulled crease 3
  // (horizontal span 2 a cos(theta)) when crease 3 has risen by 2 a sin(theta).
  ZigzagSpec s;
  const double a = s.length / s.panels;
  EXPECT_NEAR(zigzag_deployed_travel(s), 2 * a * std::sin(s.fold_angle), 1e-15);
  EXPECT_NEAR(zigzag_deployed_travel(s), 0.157569, 1e-6);  // 160 mm sin 80 deg
  EXPECT_NEAR(zigzag_default_travel(s), 0.9 * zigzag_deployed_travel(s), 1e-15);
  s.fold_angle = 83 * kDegToRad;
  EXPECT_NEAR(zigzag_deployed_travel(s), 2 * a * std::sin(83 * kDegToRad), 1e-15);
  // Panel 5 clamped: one link (panel 4) reaches straight first, at a sin(theta).
  s.fixed_panels = {1, 5};
  EXPECT_NEAR(zigzag_deployed_travel(s), a * std::sin(83 * kDegToRad), 1e-15);
  EXPECT_NEAR(build_zigzag_model(s).drives[0].deployed_at, zigzag_deployed_travel(s), 0);
}

TEST(DeploymentPeak, SummaryReportsDeploymentPeakEndForceAndLargestApart) {
  ProbeTable t;
  t.name = "gauge";
  t.kind = ProbeKind::Drive;
  t.columns = {"pull_displacement_m", "force_N"};
  for (double x : grid(0, 0.1418, 710)) t.rows.push_back({x, hump_then_taut(x)});
  const nlohmann::json j = probe_summary(t, 0.157569);
  EXPECT_NEAR(j["deployment_peak_force_N"].get<double>(), 0.14, 1e-8);
  EXPECT_NEAR(j["deployment_peak_displacement_m"].get<double>(), 0.026, 1e-6);
  EXPECT_NEAR(j["peak_force_N"].get<double>(), hump_then_taut(0.1418), 1e-12);
  EXPECT_NEAR(j["peak_displacement_m"].get<double>(), 0.1418, 1e-12);
  EXPECT_NEAR(j["end_force_N"].get<double>(), hump_then_taut(0.1418), 1e-12);
  EXPECT_NEAR(j["deployed_at_m"].get<double>(), 0.157569, 0);
  EXPECT_NEAR(j["deployment_window_m"][1].get<double>(), 0.1418, 1e-12);
  // Deployed at 20 mm: the hump has not fallen back inside the window.
  EXPECT_TRUE(probe_summary(t, 0.02)["deployment_peak_force_N"].is_null());
  EXPECT_TRUE(probe_summary(t)["deployed_at_m"].is_null());
}

}  // namespace deployment_peak_test
}  // namespace finseg
