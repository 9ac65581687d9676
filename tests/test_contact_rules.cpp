// Which pairs may touch (docs/contact.md, "Which pairs"): segments that share an edge or a
// corner through the force elements never touch, also across a glued seam whose two sides lie
// far apart on the flat sheet; pairs within the crease zone on the flat sheet never touch;
// every other pair does where the plates overlap.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "collision/contact_forces.hpp"
#include "collision/pair_rules.hpp"
#include "contact_test_util.hpp"

namespace finseg {
namespace contact_rules_test {

constexpr double kL = 0.01, kT = 1e-4;

// A square segment of edge `edge` (m) with its centroid at p (world, flat, z up) and at c_M
// on the flat sheet.
int add_cell(Model& m, const Vec3& p, const Vec2& c_M, double edge = kL) {
  BodyDef b = test::plate(fmt::format("c{}", m.bodies.size()), 1e-5, Vec3(edge, edge, kT), p);
  b.centroid_M = c_M;
  m.bodies.push_back(b);
  return static_cast<int>(m.bodies.size()) - 1;
}

// A stiff element at the middle of the shared side of cells i and j (flat, adjacent in 3-D).
void join(Model& m, int i, int j) {
  ElementDef e;
  e.outer = i;
  e.inner = j;
  const Vec3 P = 0.5 * (m.bodies[i].p0_W + m.bodies[j].p0_W);
  e.c_outer_B = P - m.bodies[i].p0_W;
  e.c_inner_B = P - m.bodies[j].p0_W;
  e.K << 1e3, 1e3, 1e3, 1, 1, 1;
  m.elements.push_back(e);
}

Model with_contact(Model m) {
  m.contact.enabled = true;
  m.contact.stiffness = 1e5;
  m.finalize_dofs();
  return m;
}

// Four cells around one corner, 2 x 2 in 3-D: P (lower left), Q (lower right), R (upper
// left), S (upper right). On the flat sheet Q and S lie 50 mm to the right: P-Q is a glued
// seam (an element joins them, their material outlines are far apart). R-Q and R-S meet only
// at the seam's corner (R-S also along the seam's continuation, which no element joins), P-S
// diagonally. The plates overlap by their thickness along every shared side and corner, and
// none of them may touch; a fifth, smaller cell T laid flat over the middle of P (far on the
// sheet, not joined) does.
TEST(ContactRules, CellsMeetingAtACornerAcrossAGluedSeamNeverTouch) {
  Model m;
  const double far = 5 * kL;
  const int P = add_cell(m, Vec3(0.5 * kL, 0.5 * kL, 0), Vec2(0.5 * kL, 0.5 * kL));
  const int Q = add_cell(m, Vec3(1.5 * kL, 0.5 * kL, 0), Vec2(far + 0.5 * kL, 0.5 * kL));
  const int R = add_cell(m, Vec3(0.5 * kL, 1.5 * kL, 0), Vec2(0.5 * kL, 1.5 * kL));
  const int S = add_cell(m, Vec3(1.5 * kL, 1.5 * kL, 0), Vec2(far + 0.5 * kL, 1.5 * kL));
  join(m, P, Q);  // the seam
  join(m, P, R);
  join(m, Q, S);
  const int T = add_cell(m, Vec3(0.5 * kL, 0.5 * kL, 0.9 * kT), Vec2(10 * kL, 0.5 * kL), 0.5 * kL);
  m = with_contact(m);
  const PairRules rules(m);
  for (auto [a, b] : {std::pair{P, Q}, {P, R}, {Q, S}, {R, Q}, {R, S}, {P, S}})
    EXPECT_FALSE(rules.may_touch(a, b)) << a << "-" << b;
  EXPECT_TRUE(rules.may_touch(P, T));
  const ContactSummary sum = contact_summary(m, initial_state(m));
  ASSERT_EQ(sum.pairs.size(), 1u);
  EXPECT_EQ(sum.pairs[0].a, P);
  EXPECT_EQ(sum.pairs[0].b, T);
  EXPECT_NEAR(sum.max_penetration, 0.1 * kT, 1e-12);

  // The old rule (material distance only) let the corner cells across the seam touch: with
  // the seam's element taken away R, S and Q are free plates that overlap by the thickness.
  Model cut = m;
  cut.elements.erase(cut.elements.begin());
  EXPECT_TRUE(PairRules(cut).may_touch(R, Q));
}

// Two cells stacked face to face (a flat fold), a gap g apart on the flat sheet and not
// joined: inside the crease zone (default 2 t) they never touch, beyond it they do; an
// explicit crease_zone replaces the default.
TEST(ContactRules, PairsInsideTheCreaseZoneNeverTouch) {
  for (double gap_t : {0.5, 1.5, 2.5}) {
    Model m;
    const int a = add_cell(m, Vec3::Zero(), Vec2(0.5 * kL, 0.5 * kL));
    const int b = add_cell(m, Vec3(0, 0, 0.9 * kT), Vec2(1.5 * kL + gap_t * kT, 0.5 * kL));
    m = with_contact(m);
    EXPECT_EQ(PairRules(m).may_touch(a, b), gap_t > 2) << gap_t << " t";
    EXPECT_EQ(contact_summary(m, initial_state(m)).pairs.size(), gap_t > 2 ? 1u : 0u);
    m.contact.crease_zone = 0.0;
    EXPECT_TRUE(PairRules(m).may_touch(a, b)) << gap_t << " t, no crease zone";
    m.contact.crease_zone = 3 * kT;
    EXPECT_FALSE(PairRules(m).may_touch(a, b)) << gap_t << " t, zone 3 t";
  }
}

}  // namespace contact_rules_test
}  // namespace finseg
