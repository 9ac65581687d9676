// A joint bent through a half turn: its relative rotation is unwrapped against the last
// accepted one, so the linear rotational spring keeps M = -K beta and U = K beta^2 / 2 past
// beta = pi (log R alone would flip the couple there), the closed-form Jacobian matches
// central differences, and a plate's bending energy stays quadratic in the bend.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>

#include "collision/contact_forces.hpp"
#include "core/so3.hpp"
#include "elements/assemble.hpp"
#include "elements/bushing.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "jacobian_test_util.hpp"
#include "patterns/fold_format.hpp"

namespace finseg {
namespace joint_half_turn_test {

constexpr double kA = 0.05;                // plate length, m
const Vec3 kTurnStiffness(0.7, 0.5, 0.9);  // N m / rad about F's x, y, z

// Two plates joined along F's y axis at the origin (no crease): outer fixed at x < 0, inner
// at x > 0 bent by `beta` about +y through the joint's point.
Model two_plates() {
  Model m;
  for (int i = 0; i < 2; ++i) {
    BodyDef b;
    b.name = i == 0 ? "outer" : "inner";
    set_box(b, Vec3(kA, 0.04, 1e-4), 1e-3);
    m.bodies.push_back(b);
  }
  m.bodies[0].p0_W = Vec3(-kA / 2, 0, 0);
  m.bodies[0].fixed = true;
  m.bodies[1].p0_W = Vec3(kA / 2, 0, 0);
  ElementDef e;
  e.outer = 0;
  e.inner = 1;
  e.c_outer_B = Vec3(kA / 2, 0, 0);
  e.c_inner_B = Vec3(-kA / 2, 0, 0);
  e.K << 3e3, 2e3, 4e3, kTurnStiffness.x(), kTurnStiffness.y(), kTurnStiffness.z();
  e.name = "joint";
  m.elements.push_back(e);
  m.finalize_dofs();
  return m;
}

void bend(State& s, double beta) {
  s.R_WB[1] = so3_exp<double>(Vec3(0, beta, 0));
  s.p_W[1] = s.R_WB[1] * Vec3(kA / 2, 0, 0);
}

TEST(JointHalfTurn, RotationNearIsTheTurnOfLogNearestThePreviousOne) {
  const Vec3 u = Vec3(1, -2, 0.5).normalized();
  for (const double beta : {0.3, 3.0, 3.2, 4.5, 6.0}) {
    const Mat3 R = so3_exp<double>(Vec3(beta * u));
    const Vec3 near = (beta - 0.05) * u;
    EXPECT_LT((rotation_near<double>(R, near) - beta * u).norm(), 1e-12) << beta;
  }
  // From zero it is log R itself, |theta| <= pi.
  const Mat3 R = so3_exp<double>(Vec3(3.5 * u));
  EXPECT_LT((rotation_near<double>(R, Vec3::Zero()) + (2 * kPi - 3.5) * u).norm(), 1e-12);
}

TEST(JointHalfTurn, LinearSpringKeepsItsMomentAndEnergyPastHalfATurn) {
  const Model m = two_plates();
  State s = initial_state(m);
  const double k = kTurnStiffness.y();
  for (int i = 1; i <= 32; ++i) {  // to 1.6 pi in steps of 0.05 pi, each one accepted
    const double beta = 0.05 * kPi * i;
    bend(s, beta);
    BodyForces f;
    compute_forces(m, s, f);
    SCOPED_TRACE(beta);
    EXPECT_NEAR(f.tau_W[1].y(), -k * beta, 1e-12 * k * beta);
    EXPECT_NEAR(f.potential_energy, 0.5 * k * beta * beta, 1e-12 * k * beta * beta);
    commit_history(m, s);
  }
  EXPECT_NEAR(s.history[0].rotation_F.y(), 1.6 * kPi, 1e-12);
}

// The same with contact on: past pi the joint's stop (collision/joint_stops.hpp) adds the
// contact law's force F = K delta^e at delta = (beta - pi) r, r = a / 2, as the couple F r.
Model two_plates_in_contact() {
  Model m = two_plates();
  m.contact.enabled = true;
  m.contact.stiffness = 2e6;  // N/m^1.5
  m.contact.exponent = 1.5;
  return m;
}

TEST(JointHalfTurn, StopPastHalfATurnIsTheContactLawAtTheCentroidsDistance) {
  const Model m = two_plates_in_contact();
  State s = initial_state(m);
  const double k = kTurnStiffness.y(), r = kA / 2, K = m.contact.stiffness;
  for (int i = 1; i <= 22; ++i) {  // to 1.1 pi
    const double beta = 0.05 * kPi * i;
    bend(s, beta);
    BodyForces f;
    compute_forces(m, s, f);
    const double delta = std::max(0.0, (beta - kPi) * r);
    const double moment = k * beta + K * std::pow(delta, 1.5) * r;
    const double energy = 0.5 * k * beta * beta + K * std::pow(delta, 2.5) / 2.5;
    SCOPED_TRACE(beta);
    EXPECT_NEAR(f.tau_W[1].y(), -moment, 1e-12 * moment);
    EXPECT_NEAR(f.potential_energy, energy, 1e-12 * energy);
    commit_history(m, s);
  }
}

TEST(JointHalfTurn, ContactProbesCountAStopAsOnePoint) {
  const Model m = two_plates_in_contact();
  State s = initial_state(m);
  for (int i = 1; i <= 21; ++i) {  // to 1.05 pi
    bend(s, 0.05 * kPi * i);
    commit_history(m, s);
  }
  const double delta = 0.05 * kPi * kA / 2, force = m.contact.stiffness * std::pow(delta, 1.5);
  const ContactSummary c = contact_summary(m, s);
  EXPECT_EQ(c.active, 1);
  EXPECT_NEAR(c.total_normal_force, force, 1e-12 * force);
  EXPECT_NEAR(c.max_penetration, delta, 1e-12 * delta);
  ASSERT_EQ(c.pairs.size(), 1u);
  EXPECT_EQ(c.pairs[0].a, 0);
  EXPECT_EQ(c.pairs[0].b, 1);
  EXPECT_EQ(contact_summary(two_plates(), s).active, 0);  // contact off: no stop
}

// The joint made a crease (a linear law): its stop acts on the unwrapped fold angle.
Model creased(Model m) {
  m.elements[0].crease = 0;
  m.creases.push_back({std::make_shared<LinearCreaseLaw>(0.3, 0.0), 0.0});
  return m;
}

TEST(JointHalfTurn, CreaseStopPastHalfATurnIsTheContactLaw) {
  const Model off = creased(two_plates()), on = creased(two_plates_in_contact());
  State s = initial_state(on);
  const double r = kA / 2, K = on.contact.stiffness;
  for (int i = 1; i <= 22; ++i) {  // to 1.1 pi
    const double beta = 0.05 * kPi * i;
    bend(s, beta);
    BodyForces f_on, f_off;
    compute_forces(on, s, f_on);
    compute_forces(off, s, f_off);
    const double delta = std::max(0.0, (beta - kPi) * r);
    const double moment = K * std::pow(delta, 1.5) * r, energy = K * std::pow(delta, 2.5) / 2.5;
    SCOPED_TRACE(beta);
    EXPECT_NEAR(f_on.tau_W[1].y() - f_off.tau_W[1].y(), -moment, 1e-9 * (moment + 1e-6));
    EXPECT_NEAR(f_on.potential_energy - f_off.potential_energy, energy, 1e-9 * (energy + 1e-9));
    commit_history(on, s);
  }
  EXPECT_NEAR(s.history[0].fold_angle, 1.1 * kPi, 1e-12);
}

TEST(JointHalfTurn, JacobianMatchesCentralDifferencesPastHalfATurn) {
  for (const Model& m : {two_plates(), two_plates_in_contact(), creased(two_plates_in_contact())}) {
    for (const double beta : {kPi - 0.02, kPi + 0.02, 1.3 * kPi}) {
      State s = initial_state(m);
      for (double b = 0.1; b < beta; b += 0.1) {
        bend(s, b);
        commit_history(m, s);
      }
      bend(s, beta);
      Eigen::VectorXd dq(m.num_dofs);  // off the axis: all three rotations and translations
      for (int i = 0; i < m.num_dofs; ++i) dq[i] = (i < 3 ? 1e-4 : 0.05) * std::sin(1.3 * i + 0.2);
      apply_pose_increment(m, s, dq);
      const Eigen::MatrixXd J = test::pose_jacobian(m, s), fd = test::fd_pose_jacobian(m, s, 1e-7);
      SCOPED_TRACE(beta);
      EXPECT_LT((J - fd).cwiseAbs().maxCoeff(), 1e-6 * J.cwiseAbs().maxCoeff());
    }
  }
}

// Two 1 mm squares side by side joined by a plate edge (F, no fold angle), 2 x 2 cells each.
Model two_squares_plate() {
  const CreasePattern p = parse_fold(R"({
    "file_spec": 1.1, "frame_unit": "mm",
    "vertices_coords": [[0,0], [1,0], [2,0], [2,1], [1,1], [0,1]],
    "faces_vertices": [[0,1,4,5], [1,2,3,4]],
    "edges_vertices": [[0,1], [1,2], [2,3], [3,4], [4,5], [5,0], [1,4]],
    "edges_assignment": ["B", "B", "B", "B", "B", "B", "F"]})",
                                     "two_squares.fold");
  PatternSheetSpec spec;
  spec.subdivisions = 2;
  return build_pattern_model(p, spec);
}

TEST(JointHalfTurn, PlateBendingEnergyStaysQuadraticPastHalfATurn) {
  const Model m = two_squares_plate();
  ASSERT_FALSE(m.plate_cells.empty());
  State s = initial_state(m);
  const Vec3 hinge(1e-3, 0, 0);  // a point of the shared edge x = 1 mm, which runs along y
  double per_rad2 = 0;
  for (int i = 1; i <= 32; ++i) {  // the right square turned about the edge to 1.6 pi
    const double beta = 0.05 * kPi * i;
    const Mat3 R = so3_exp<double>(Vec3(0, beta, 0));
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      if (m.bodies[b].p0_W.x() < hinge.x()) continue;
      s.R_WB[b] = R * m.bodies[b].R0_WB;
      s.p_W[b] = hinge + R * (m.bodies[b].p0_W - hinge);
    }
    BodyForces f;
    compute_forces(m, s, f);
    if (i == 1) per_rad2 = f.potential_energy / (beta * beta);
    EXPECT_NEAR(f.potential_energy, per_rad2 * beta * beta, 1e-9 * per_rad2 * beta * beta)
        << "beta " << beta;
    commit_history(m, s);
  }
  EXPECT_GT(per_rad2, 0);
}

}  // namespace joint_half_turn_test
}  // namespace finseg
