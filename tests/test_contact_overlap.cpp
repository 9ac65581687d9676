// Plates that start overlapping under `contact.initial_overlap: ignore` (docs/contact.md,
// "Layers that start overlapping"), against closed forms: a plate set into another by d0 comes
// to rest under its weight at d0 + (m g / K)^(1/e) below touching (Hertz, eq. 18), where the
// default pushes it out to (m g / K)^(1/e); the overlap shrinks as the plates part and never
// grows back, and a part-way return meets K (d - overlap)^e; plates that coincide at the start
// take their order from the way they part.
#include <gtest/gtest.h>

#include <cmath>

#include "collision/contact_forces.hpp"
#include "collision/contact_laws.hpp"
#include "contact_test_util.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace contact_overlap_test {

constexpr double kG = 9.81;
constexpr double kThick = 2e-4;  // plate thickness, m
constexpr double kMass = 1e-3;   // the free plate, kg
constexpr double kSide = 0.02;   // both plates square, m

// A clamped plate at the origin and a free one above it at height z (z < kThick: overlapping),
// contact stiffness K such that the free plate's weight sinks it 10 um.
Model two_plates(double z, InitialOverlap overlap) {
  Model m;
  m.gravity_W = Vec3(0, 0, -kG);
  m.bodies.push_back(
      test::plate("base", 1, Vec3(kSide, kSide, kThick), Vec3::Zero(), Mat3::Identity(), true));
  m.bodies.push_back(test::plate("top", kMass, Vec3(kSide, kSide, kThick), Vec3(0, 0, z)));
  m.contact = test::continuous_contact(suggest_contact(kMass, kG, 1e-5), 0.5, 0.4);
  m.contact.stiffness = kMass * kG / std::pow(1e-5, m.contact.exponent);
  m.contact.initial_overlap = overlap;
  m.finalize_dofs();
  return m;
}

// Height where the free plate comes to rest under its weight (backward Euler, 40 periods of its
// bounce on the contact; the static solver cannot start it: at the start nothing pushes, and
// the Hertz law has no slope at zero penetration).
double rest_height(double z0, InitialOverlap overlap) {
  const Model m = two_plates(z0, overlap);
  State s = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Implicit;
  set.t_end = 0.2;
  set.output_interval = set.t_end;
  set.dt_max = 1e-3;
  const SolverStats st = run_solver(m, s, set, [](const State&, const BodyForces&) {});
  EXPECT_EQ(st.status, "ok") << st.message;
  return s.p_W[1].z();
}

TEST(ContactOverlap, PlateSetIntoAnotherRestsBeyondItsOverlap) {
  const Model m = two_plates(0, InitialOverlap::Push);
  const double sink = std::pow(kMass * kG / m.contact.stiffness, 1 / m.contact.exponent);
  const double d0 = 0.5 * kThick;
  EXPECT_NEAR(rest_height(kThick - d0, InitialOverlap::Ignore), kThick - d0 - sink, 1e-3 * sink);
  EXPECT_NEAR(rest_height(kThick - d0, InitialOverlap::Push), kThick - sink, 1e-3 * sink);
}

// The free plate moved to height z (no velocity) and its contact history committed.
void move_and_commit(const Model& m, State& s, double z) {
  s.p_W[1] = Vec3(0, 0, z);
  commit_contact_history(m, s);
}

TEST(ContactOverlap, OverlapShrinksAsPlatesPartAndNeverGrows) {
  const Model m = two_plates(0, InitialOverlap::Ignore);  // coinciding: a whole thickness deep
  State s = initial_state(m);
  commit_contact_history(m, s, true);
  ASSERT_FALSE(s.contact.anchors.empty());
  for (const ContactAnchor& a : s.contact.anchors) EXPECT_DOUBLE_EQ(a.overlap, kThick);
  EXPECT_EQ(contact_summary(m, s).active, 0);

  move_and_commit(m, s, 0.3 * kThick);  // parted: 0.7 t left
  for (const ContactAnchor& a : s.contact.anchors) EXPECT_NEAR(a.overlap, 0.7 * kThick, 1e-18);
  EXPECT_EQ(contact_summary(m, s).active, 0);

  s.p_W[1] = Vec3(0, 0, 0.2 * kThick);  // back a third of the way: 0.1 t beyond the overlap
  const ContactSummary c = contact_summary(m, s);
  const double expected = m.contact.stiffness * std::pow(0.1 * kThick, m.contact.exponent);
  EXPECT_NEAR(c.total_normal_force, expected, 1e-9 * expected);
  EXPECT_NEAR(c.max_penetration, 0.1 * kThick, 1e-15);
  ASSERT_EQ(c.pairs.size(), 1u);
  EXPECT_NEAR(c.pairs[0].f_b_W.z(), expected, 1e-9 * expected);  // the top plate pushed up

  commit_contact_history(m, s);  // pressing further in does not give the overlap back
  for (const ContactAnchor& a : s.contact.anchors) EXPECT_NEAR(a.overlap, 0.7 * kThick, 1e-18);

  move_and_commit(m, s, 1.5 * kThick);  // apart: no history left
  EXPECT_TRUE(s.contact.anchors.empty());
}

TEST(ContactOverlap, CoincidingPlatesTakeTheirOrderFromHowTheyPart) {
  for (const double dir : {1.0, -1.0}) {
    const Model m = two_plates(0, InitialOverlap::Ignore);
    State s = initial_state(m);
    commit_contact_history(m, s, true);
    move_and_commit(m, s, dir * 0.3 * kThick);
    s.p_W[1] = Vec3(0, 0, dir * 0.2 * kThick);
    const ContactSummary c = contact_summary(m, s);
    ASSERT_EQ(c.pairs.size(), 1u) << dir;
    const double expected = m.contact.stiffness * std::pow(0.1 * kThick, m.contact.exponent);
    EXPECT_NEAR(c.pairs[0].f_b_W.z(), dir * expected, 1e-9 * expected) << dir;
  }
}

TEST(ContactOverlap, CoincidingPlatesPassFreelyUntilAQuarterThicknessApart) {
  const Model m = two_plates(0, InitialOverlap::Ignore);
  State s = initial_state(m);
  commit_contact_history(m, s, true);
  move_and_commit(m, s, 0.2 * kThick);  // not yet a quarter apart: no side, no force
  for (const ContactAnchor& a : s.contact.anchors) EXPECT_EQ(a.side, 0);
  s.p_W[1] = Vec3(0, 0, -0.1 * kThick);
  EXPECT_EQ(contact_summary(m, s).active, 0);
  move_and_commit(m, s, -0.25 * kThick);  // a quarter apart below: below for good
  for (const ContactAnchor& a : s.contact.anchors) {
    EXPECT_NE(a.side, 0);
    EXPECT_NEAR(a.overlap, 0.75 * kThick, 1e-18);
  }
  s.p_W[1] = Vec3(0, 0, -0.15 * kThick);
  const ContactSummary c = contact_summary(m, s);
  ASSERT_EQ(c.pairs.size(), 1u);
  const double expected = m.contact.stiffness * std::pow(0.1 * kThick, m.contact.exponent);
  EXPECT_NEAR(c.pairs[0].f_b_W.z(), -expected, 1e-9 * expected);  // the top plate pushed down
}

TEST(ContactOverlap, PushIsTheDefaultAndPushesAtTheStart) {
  EXPECT_EQ(ContactDef{}.initial_overlap, InitialOverlap::Push);
  const Model m = two_plates(0.5 * kThick, InitialOverlap::Push);
  State s = initial_state(m);
  commit_contact_history(m, s, true);
  for (const ContactAnchor& a : s.contact.anchors) EXPECT_EQ(a.overlap, 0);
  const double expected = m.contact.stiffness * std::pow(0.5 * kThick, m.contact.exponent);
  EXPECT_NEAR(contact_summary(m, s).total_normal_force, expected, 1e-9 * expected);
}

}  // namespace contact_overlap_test
}  // namespace finseg
