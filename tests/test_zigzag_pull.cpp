// Quasi-static pull of the zigzag: equilibrium and the rigid-panel closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "elements/assemble.hpp"
#include "elements/drive_gauge.hpp"
#include "generators/zigzag.hpp"
#include "solvers/solver.hpp"
#include "zigzag_linkage.hpp"

namespace finseg {
namespace zigzag_pull_test {

Vec3 total_weight(const Model& m) {
  Vec3 w = Vec3::Zero();
  for (const BodyDef& b : m.bodies) w += b.mass * m.gravity_W;
  return w;
}

// Force the clamps exert on the structure: the fixed bodies are held in equilibrium.
Vec3 clamp_reaction(const Model& m, const BodyForces& f) {
  Vec3 r = Vec3::Zero();
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    if (m.bodies[i].fixed) r -= f.f_W[i];
  }
  return r;
}

TEST(ZigzagPull, GaugeReactionsAndWeightBalance) {
  ZigzagSpec spec;
  spec.contact = false;
  const Model m = build_zigzag_model(spec);
  State st = initial_state(m);
  SolverSettings set;
  int checked = 0;
  const SolverStats stats = run_solver(m, st, set, [&](const State& s, const BodyForces& f) {
    const Vec3 gauge = drive_force(m, s, 0);
    const Vec3 sum = gauge + clamp_reaction(m, f) + total_weight(m);
    EXPECT_LE(sum.norm(), 1e-3 * gauge.norm()) << "at drive " << s.drive_s[0] << " m";
    ++checked;
  });
  ASSERT_EQ(stats.status, "ok") << stats.message;
  EXPECT_GT(checked, 50);
}

TEST(ZigzagPull, RigidPanelLimitMatchesClosedForm) {
  test::expect_rigid_panel_linkage(build_zigzag_model);
}

}  // namespace zigzag_pull_test
}  // namespace finseg
