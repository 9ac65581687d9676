// The force check (solvers/force_check.hpp): a force that jumps is told from curvature. A small
// plate is carried, within one step, from above a larger plate (beyond contact, outside its edge)
// to below its mid-plane over its face: its edge samples take the side they came from when their
// straight path crossed the plate's face, else the side they are on (docs/contact.md, "Side"),
// so where the path crosses the mid-plane exactly at the edge line their force flips.
#include <gtest/gtest.h>

#include "collision/contact_forces.hpp"
#include "contact_test_util.hpp"
#include "solvers/force_check.hpp"

namespace finseg {
namespace force_check_test {

// Plate a (20 x 10 mm) sampled on plate b (30 x 20 mm, its edge x = 15 mm), both 0.2 mm
// thick, free, contact without friction; the history committed with a's left edge `outside` beyond
// b's edge and 0.3 mm above it; then a's left edge `inside` within b's edge and 0.1 mm below.
struct Carried {
  Model model;
  State state;
  Carried(double outside, double inside) {
    const double edge = 0.015, half = 0.01;  // b's edge; a's half length
    model.bodies.push_back(
        test::plate("a", 1e-3, Vec3(2 * half, 0.01, 2e-4), Vec3(edge + outside + half, 0, 3e-4)));
    model.bodies.push_back(test::plate("b", 1e-3, Vec3(0.03, 0.02, 2e-4), Vec3::Zero()));
    model.contact.enabled = true;
    model.contact.stiffness = 1e6;
    model.finalize_dofs();
    state = initial_state(model);
    commit_contact_history(model, state);
    state.p_W[0] = Vec3(edge - inside + half, 0, -1e-4);
  }
};

int count(const std::vector<ForceMismatch>& found, ForceMismatchKind kind) {
  int n = 0;
  for (const ForceMismatch& m : found) n += m.kind == kind;
  return n;
}

TEST(ForceCheck, APathCrossingThePlateAtItsEdgeIsAJump) {
  // The path from 3 mm outside, 0.3 mm up, to 1 mm inside, 0.1 mm down crosses z = 0 at
  // 3 - (3 + 1) * 0.3 / 0.4 = 0 mm: on the edge line.
  const Carried c(3e-3, 1e-3);
  ASSERT_GE(contact_summary(c.model, c.state).active, 1);
  const std::vector<ForceMismatch> found = check_force_jacobian(c.model, c.state, 1e-7);
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(found.front().kind, ForceMismatchKind::Jump);
  EXPECT_GT(std::abs(found.front().fine), 5 * std::abs(found.front().coarse));
}

TEST(ForceCheck, APathCrossingTheFaceIsSmooth) {
  // From 1 mm outside, 0.3 mm up, to 3 mm inside, 0.1 mm down: z = 0 is crossed 2 mm within
  // the edge.
  const Carried c(1e-3, 3e-3);
  ASSERT_GE(contact_summary(c.model, c.state).active, 1);
  const std::vector<ForceMismatch> found = check_force_jacobian(c.model, c.state, 1e-7);
  EXPECT_EQ(count(found, ForceMismatchKind::Jump), 0);
  EXPECT_EQ(count(found, ForceMismatchKind::Inexact), 0);
}

}  // namespace force_check_test
}  // namespace finseg
