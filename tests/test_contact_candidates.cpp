// The contact detection's shortcuts against brute force: the candidates kept from a commit
// (a Verlet list) give a fresh search's pairs and the same forces to the bit while the
// segments stay within their margin; the rejection of plates that cannot touch from their
// vertices loses no point of a cloud of crossing, tilted plates (every sample of every pair
// tested); a plate carried through another within one step still meets the full force.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <random>

#include "collision/candidate_cache.hpp"
#include "collision/contact_forces.hpp"
#include "collision/narrowphase.hpp"
#include "collision/pair_rules.hpp"
#include "elements/assembler.hpp"

namespace finseg {
namespace contact_candidates_test {

constexpr double kThickness = 1e-3;

// n free plates of random size and pose in a 30 mm cube, contact on: many cross or overlap.
struct Cloud {
  Model model;
  State state;
  explicit Cloud(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < n; ++i) {
      BodyDef b;
      b.name = fmt::format("p{}", i);
      set_box(b, Vec3(0.01 + 0.01 * u(rng), 0.005 + 0.01 * u(rng), kThickness), 1e-4);
      model.bodies.push_back(b);
      model.dof_of_body.push_back(6 * i);
      state.p_W.push_back(Vec3(u(rng), u(rng), u(rng)) * 0.03);
      const Vec3 axis = Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized();
      // A third of the plates nearly level, so that parallel layers are among the pairs.
      const double angle = i % 3 == 0 ? 0.1 * u(rng) : kPi * u(rng);
      state.R_WB.push_back(Eigen::AngleAxisd(angle, axis).toRotationMatrix());
      state.v_W.push_back(Vec3::Zero());
      state.w_W.push_back(Vec3::Zero());
    }
    model.num_dofs = 6 * n;
    ContactDef& c = model.contact;
    c.enabled = true;
    c.stiffness = 1e6;
    c.exponent = 1.5;
    c.damping = 0;
    c.damping_depth = 1e-4;
  }
};

BodyForces contact_forces(const Model& m, const State& s) {
  BodyForces f;
  f.f_W.assign(m.bodies.size(), Vec3::Zero());
  f.tau_W.assign(m.bodies.size(), Vec3::Zero());
  Assembler as(m, s, f, nullptr);
  add_contact_forces(m, s, as);
  return f;
}

// Contact points of a state without history, every sample of every pair tested: the side a
// point takes is entry_side()'s without history (nearly parallel plates: the source centre's
// side where the point lies within the two half thicknesses of the target's plane; else the
// point's own).
int brute_force_points(const Model& m, const State& s) {
  int points = 0;
  const int n = static_cast<int>(m.bodies.size());
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      const PlateShape sa = plate_shape(m.bodies[a]), sb = plate_shape(m.bodies[b]);
      const DirectionShares shares = direction_shares(sa, sb);
      for (int dir = 0; dir < 2; ++dir) {
        if ((dir == 0 ? shares.a_on_b : shares.b_on_a) <= 0) continue;
        const int src = dir == 0 ? a : b, tgt = dir == 0 ? b : a;
        const PlateShape& ss = dir == 0 ? sa : sb;
        const PlateShape& st = dir == 0 ? sb : sa;
        const BodyKin<double> G{s.p_W[tgt], s.R_WB[tgt], Vec3::Zero(), Vec3::Zero()};
        const Vec3 n_t = s.R_WB[tgt].col(2);
        const bool parallel = std::abs(n_t.dot(s.R_WB[src].col(2))) > std::cos(30 * kDegToRad);
        for (const PlateSample& k : plate_samples(ss, m.contact.samples_per_edge)) {
          const Vec3 p_W = s.p_W[src] + s.R_WB[src] * k.r_B;
          const double own = n_t.dot(p_W - G.p_W), reach = ss.r + st.r;
          const double h =
              parallel && std::abs(own) < reach ? n_t.dot(s.p_W[src] - s.p_W[tgt]) : own;
          if (point_on_plate(G, st, p_W, ss.r, h >= 0 ? 1 : -1).depth > 0) ++points;
        }
      }
    }
  return points;
}

TEST(ContactCandidates, NoPointOfACloudOfTiltedPlatesIsLost) {
  int touching = 0;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const Cloud c(40, seed);
    const ContactSummary sum = contact_summary(c.model, c.state);
    EXPECT_EQ(sum.active, brute_force_points(c.model, c.state)) << "seed " << seed;
    touching += sum.active;
  }
  EXPECT_GT(touching, 100);  // the clouds do touch
}

TEST(ContactCandidates, KeptCandidatesGiveTheFreshSearchsPairsAndForces) {
  Cloud c(40, 7);
  commit_contact_history(c.model, c.state, true);
  ASSERT_NE(c.state.contact.candidates, nullptr);
  const ContactCandidates& kept = *c.state.contact.candidates;
  EXPECT_EQ(kept.margin, kThickness);  // no earlier commit: the thickness
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Aabb> boxes;
  BroadPhase broad;
  for (int trial = 0; trial < 20; ++trial) {
    // Every plate moved and turned so that its points travel up to 0.85 of the margin.
    State s = c.state;
    for (std::size_t i = 0; i < s.p_W.size(); ++i) {
      const double reach = outline_radius(c.model.bodies[i].outline_B);
      const Vec3 turn = Vec3(u(rng), u(rng), u(rng)).normalized() * (0.4 * kThickness / reach);
      s.p_W[i] += Vec3(u(rng), u(rng), u(rng)).normalized() * 0.4 * kThickness;
      s.R_WB[i] = Eigen::AngleAxisd(turn.norm(), turn.normalized()) * s.R_WB[i];
    }
    ASSERT_TRUE(covers(kept, c.model, s)) << trial;
    EXPECT_EQ(present_pairs(kept, c.model, s, boxes),
              contact_candidates(c.model, s, PairRules(c.model), broad, boxes))
        << trial;
    State fresh = s;
    fresh.contact.candidates = nullptr;
    const BodyForces f_kept = contact_forces(c.model, s), f_fresh = contact_forces(c.model, fresh);
    for (std::size_t i = 0; i < s.p_W.size(); ++i) {
      EXPECT_EQ(f_kept.f_W[i], f_fresh.f_W[i]) << trial << " body " << i;
      EXPECT_EQ(f_kept.tau_W[i], f_fresh.tau_W[i]) << trial << " body " << i;
    }
  }
  // One plate moved by the margin: the kept candidates no longer serve.
  State far = c.state;
  far.p_W[3].x() += kThickness;
  EXPECT_FALSE(covers(kept, c.model, far));
  // Nor do they serve another model with the same segments.
  const Model copy = c.model;
  EXPECT_FALSE(covers(kept, copy, c.state));
}

TEST(ContactCandidates, APlateCarriedThroughAnotherInOneStepMeetsTheFullForce) {
  // Two parallel 20 mm plates tilted 45 degrees (their boxes overlap), the upper 3 thicknesses
  // above the lower along its normal; one step later 3 below: every vertex beyond the
  // contact's reach, yet it came through the lower plate's face.
  Cloud c(2, 1);
  for (BodyDef& b : c.model.bodies) set_box(b, Vec3(0.02, 0.02, kThickness), 1e-4);
  const Mat3 R = Eigen::AngleAxisd(kPi / 4, Vec3::UnitX()).toRotationMatrix();
  const Vec3 n = R.col(2), shift(0.001, 0.001, 0);
  c.state.p_W = {Vec3::Zero(), R * shift + 3 * kThickness * n};
  c.state.R_WB = {R, R};
  commit_contact_history(c.model, c.state, true);
  EXPECT_EQ(contact_summary(c.model, c.state).active, 0);
  State through = c.state;
  through.p_W[1] = R * shift - 3 * kThickness * n;
  const BodyForces f = contact_forces(c.model, through);
  // Entered from above: pushed back up by the force of a 4-thickness penetration.
  EXPECT_GT(f.f_W[1].dot(n), 0);
  const ContactSummary sum = contact_summary(c.model, through);
  ASSERT_GT(sum.active, 0);
  EXPECT_NEAR(sum.max_penetration, 4 * kThickness, 1e-12);
  // Without the history the same poses are a plate lying clear below the other.
  State clear = through;
  clear.contact = ContactState{};
  EXPECT_EQ(contact_summary(c.model, clear).active, 0);
}

}  // namespace contact_candidates_test
}  // namespace finseg
