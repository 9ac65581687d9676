// Phase detection rule and the panel bend measure.
#include <gtest/gtest.h>

#include <cmath>

#include "core/so3.hpp"
#include "generators/sheet.hpp"
#include "probes/deployment_phases.hpp"

namespace finseg {
namespace deployment_phases_test {

TEST(DeploymentPhases, RuleOnSyntheticSamples) {
  std::vector<PhaseSample> s;
  for (int i = 0; i <= 10; ++i) s.push_back({0.01 * i, i >= 4 ? 2 : 0, i >= 7 ? 0.2 : 0.01});
  const DeploymentPhases p = detect_phases(s, 0.1);
  EXPECT_DOUBLE_EQ(p.initial_deformation, 0.0);
  EXPECT_DOUBLE_EQ(p.contact, 0.04);
  EXPECT_DOUBLE_EQ(p.bending, 0.07);
  for (auto& x : s) x.active_contacts = 0;
  const DeploymentPhases q = detect_phases(s, 0.1);
  EXPECT_TRUE(std::isnan(q.contact));
  EXPECT_DOUBLE_EQ(q.bending, 0.07);
}

TEST(DeploymentPhases, BendOfACircularArcIsItsTurningAngle) {
  SheetSpec spec;
  spec.cells_along = 10;
  const Model m = build_sheet_model(spec);
  State st = initial_state(m);
  // Bend the flat sheet into an arc turning by 0.6 rad: body i turns by 0.06 per joint.
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    st.R_WB[i] = so3_exp<double>(Vec3(0, 0.06 * static_cast<double>(i), 0));
  }
  EXPECT_NEAR(panel_bend_angle(m, st, 0), 0.6, 1e-12);
}

}  // namespace deployment_phases_test
}  // namespace finseg
