// Crease element: exact fold angle through +-180 deg and over several turns, forces as the
// exact gradient of the energy, opening count, damping about the crease line.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/so3.hpp"
#include "elements/assemble.hpp"
#include "elements/bushing.hpp"
#include "elements/crease_history.hpp"
#include "elements/crease_law.hpp"
#include "elements/crease_laws/measured.hpp"
#include "jacobian_test_util.hpp"
#include "solvers/dofs.hpp"

namespace finseg {
namespace crease_element_test {

Mat3 rot(const Vec3& phi) {
  return so3_exp<double>(phi);
}

// Two unit-ish plates joined along F's y axis at the origin: outer (F) occupies x < 0,
// inner (E) x > 0 in its own frame, folded by `fold` about +y.
Model two_plates(std::shared_ptr<const CreaseLaw> law, double fold, bool outer_fixed) {
  Model m;
  const double a = 0.05, w = 0.04, t = 1e-4;
  for (int i = 0; i < 2; ++i) {
    BodyDef b;
    b.name = i == 0 ? "outer" : "inner";
    set_box(b, Vec3(a, w, t), 1e-3);
    m.bodies.push_back(b);
  }
  m.bodies[0].p0_W = Vec3(-a / 2, 0, 0);
  m.bodies[0].fixed = outer_fixed;
  m.bodies[1].R0_WB = rot(Vec3(0, fold, 0));
  m.bodies[1].p0_W = m.bodies[1].R0_WB * Vec3(a / 2, 0, 0);
  ElementDef e;
  e.outer = 0;
  e.inner = 1;
  e.c_outer_B = Vec3(a / 2, 0, 0);
  e.c_inner_B = Vec3(-a / 2, 0, 0);
  e.K << 3e3, 2e3, 4e3, 0.7, 0.0, 0.9;
  e.C << 0.1, 0.1, 0.1, 1e-3, 2e-3, 3e-3;
  e.crease = 0;
  e.name = "crease";
  m.elements.push_back(e);
  m.creases.push_back({std::move(law), fold});
  m.finalize_dofs();
  return m;
}

CreaseData cubic_data() {
  CreaseData d;
  d.source = "cubic";
  CreaseCurve c1, c2;
  c2.opening = 2;
  for (double deg : {5.0, 30.0, 60.0, 90.0, 120.0, 175.0}) {
    const double u = deg / 100;
    c1.angle_deg.push_back(deg);
    c1.moment.push_back(0.001 + 0.004 * u - 0.0005 * u * u + 0.0003 * u * u * u);
    c2.angle_deg.push_back(deg);
    c2.moment.push_back(0.002 + 0.008 * u);
  }
  d.curves = {c1, c2};
  return d;
}

// Generalized forces of the free bodies against central differences of the energy.
void expect_forces_are_energy_gradient(const Model& m, const State& st) {
  BodyForces f;
  compute_forces(m, st, f);
  const Eigen::VectorXd g = generalized_forces(m, f);
  const double h = 1e-7;
  for (int c = 0; c < m.num_dofs; ++c) {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(m.num_dofs);
    e[c] = h;
    State a = st, b = st;
    apply_pose_increment(m, a, e);
    apply_pose_increment(m, b, -e);
    BodyForces fa, fb;
    compute_forces(m, a, fa);
    compute_forces(m, b, fb);
    const double dU = (fa.potential_energy - fb.potential_energy) / (2 * h);
    EXPECT_NEAR(g[c], -dU, 1e-6 * (1 + std::abs(dU))) << "dof " << c;
  }
}

TEST(CreaseElement, ForcesAreExactEnergyGradient) {
  MeasuredLawOptions o;
  const auto measured = std::make_shared<MeasuredCreaseLaw>(cubic_data(), o);
  const auto linear = std::make_shared<LinearCreaseLaw>(0.03, 2.0);
  for (const std::shared_ptr<const CreaseLaw>& law :
       {std::shared_ptr<const CreaseLaw>(measured), std::shared_ptr<const CreaseLaw>(linear)}) {
    for (double fold : {2.4, -2.4, 0.3, 3.0}) {
      Model m = two_plates(law, fold, false);
      State st = initial_state(m);
      // A generic strained pose: twist, in-plane rotation and stretch besides the fold.
      Eigen::VectorXd dq(m.num_dofs);
      for (int i = 0; i < m.num_dofs; ++i) dq[i] = 0.02 * std::sin(1.7 * i + 0.4);
      apply_pose_increment(m, st, dq);
      commit_crease_history(m, st);
      expect_forces_are_energy_gradient(m, st);
    }
  }
}

TEST(CreaseElement, JacobianMatchesFiniteDifferences) {
  const auto law = std::make_shared<MeasuredCreaseLaw>(cubic_data(), MeasuredLawOptions{});
  Model m = two_plates(law, -2.2, false);
  State st = initial_state(m);
  Eigen::VectorXd dq(m.num_dofs), v(m.num_dofs);
  for (int i = 0; i < m.num_dofs; ++i) {
    dq[i] = 0.02 * std::sin(1.3 * i + 0.2);
    v[i] = 0.1 * std::cos(0.7 * i);
  }
  apply_pose_increment(m, st, dq);
  set_velocity(m, st, v);
  commit_crease_history(m, st);
  BodyForces f;
  ForceJacobian jac;
  compute_forces(m, st, f, &jac);
  const Eigen::MatrixXd Jq = jac.dq;
  const double h = 1e-7;
  for (int c = 0; c < m.num_dofs; ++c) {
    const Eigen::VectorXd fd = test::fd_pose_column(m, st, c, h);
    EXPECT_LE((fd - Jq.col(c)).norm(), 1e-5 * (1 + Jq.col(c).norm())) << "column " << c;
  }
}

// Rotates the inner plate about the crease line in small steps, committing history.
void turn_and_check(double fold0, double step, int n) {
  const double k = 0.02;
  Model m = two_plates(std::make_shared<LinearCreaseLaw>(k, 0.0), fold0, true);
  State st = initial_state(m);
  const double a = 2 * m.bodies[1].outline_B[1].x();  // plate length
  for (int i = 1; i <= n; ++i) {
    const double alpha = fold0 + i * step;
    // A small twist about the plate's own x axis must not disturb the fold angle.
    st.R_WB[1] = rot(Vec3(0, alpha, 0)) * rot(Vec3(0.01, 0, 0));
    st.p_W[1] = rot(Vec3(0, alpha, 0)) * Vec3(a / 2, 0, 0);
    commit_crease_history(m, st);
    ASSERT_NEAR(st.history[0].fold_angle, alpha, 1e-12) << "step " << i;
    // Moment about the crease line on the inner plate: -k alpha (s = sign of fold0).
    st.R_WB[1] = rot(Vec3(0, alpha, 0));
    BodyForces f;
    compute_forces(m, st, f);
    const double s = fold0 < 0 ? -1 : 1;
    ASSERT_NEAR(f.tau_W[1].y(), -s * k * (s * alpha - 0.0), 1e-12) << "step " << i;
    ASSERT_NEAR(f.tau_W[1].x(), 0.0, 1e-12);
  }
}

TEST(CreaseElement, FoldAngleContinuousThroughHalfTurnAndSeveralTurns) {
  turn_and_check(0.0, 3 * kDegToRad, 400);   // 0 -> 1200 deg: through 180, 360, ...
  turn_and_check(0.0, -3 * kDegToRad, 400);  // the other way
  turn_and_check(-2.9, 2 * kDegToRad, 600);  // from a negative fold through 0 and +180
  turn_and_check(kPi, -5 * kDegToRad, 300);  // folded flat shut, opened and turned on
}

TEST(CreaseElement, FlatFoldBothDirections) {
  for (double s : {1.0, -1.0}) {
    // Folded flat shut (|alpha| = 180 deg) in either direction: the measured law sees
    // opening angle 0 in both, so the moments are mirror images.
    const auto law = std::make_shared<MeasuredCreaseLaw>(cubic_data(), MeasuredLawOptions{});
    const double fold = s * (kPi - 10 * kDegToRad);
    Model m = two_plates(law, fold, true);
    State st = initial_state(m);
    BodyForces f;
    compute_forces(m, st, f);
    const double M10 = law->opening_moment(10 * kDegToRad, 1).value;
    // dU/dalpha = -s M(theta): the couple on the inner plate, -dU/dalpha about y, opens it.
    EXPECT_NEAR(f.tau_W[1].y(), s * M10, 1e-14);
  }
}

TEST(CreaseElement, OpeningCountSwitchesCurve) {
  const auto law = std::make_shared<MeasuredCreaseLaw>(cubic_data(), MeasuredLawOptions{});
  const double fold0 = kPi - 10 * kDegToRad;
  Model m = two_plates(law, fold0, true);
  State st = initial_state(m);
  const double a = 2 * m.bodies[1].outline_B[1].x();  // plate length
  auto set_opening = [&](double theta_deg) {
    const double alpha = kPi - theta_deg * kDegToRad;
    st.R_WB[1] = rot(Vec3(0, alpha, 0));
    st.p_W[1] = st.R_WB[1] * Vec3(a / 2, 0, 0);
    commit_crease_history(m, st);
  };
  // Open to 150 deg and close to 10 deg, twice; the default rule: opened above 90, closed
  // below 30 deg.
  std::vector<int> counts;
  for (int cycle = 0; cycle < 2; ++cycle) {
    for (double th = 10; th <= 150; th += 5) set_opening(th);
    EXPECT_TRUE(st.history[0].opened);
    EXPECT_EQ(st.history[0].openings, cycle);
    for (double th = 150; th >= 10; th -= 5) set_opening(th);
    EXPECT_FALSE(st.history[0].opened);
    EXPECT_EQ(st.history[0].openings, cycle + 1);
  }
  // Opening halfway (to 60 deg) and back does not count.
  for (double th = 10; th <= 60; th += 5) set_opening(th);
  for (double th = 60; th >= 10; th -= 5) set_opening(th);
  EXPECT_EQ(st.history[0].openings, 2);
  // Now the law uses the last measured curve (opening 2).
  set_opening(45);
  BodyForces f;
  compute_forces(m, st, f);
  EXPECT_NEAR(f.tau_W[1].y(), law->opening_moment(45 * kDegToRad, 2).value, 1e-14);
  EXPECT_NEAR(law->opening_moment(45 * kDegToRad, 2).value, 0.002 + 0.008 * 0.45, 1e-15);
}

TEST(CreaseElement, DampingAboutTheCreaseLine) {
  Model m = two_plates(std::make_shared<LinearCreaseLaw>(0.0, 1.0), 1.0, true);
  State st = initial_state(m);
  const double wy = 0.7;
  st.w_W[1] = Vec3(0, wy, 0);
  st.v_W[1] = st.w_W[1].cross(st.p_W[1]);  // turning about the crease line through the origin
  BodyForces f;
  compute_forces(m, st, f);
  EXPECT_NEAR(f.tau_W[1].y(), -m.elements[0].C[4] * wy, 1e-15);
}

}  // namespace crease_element_test
}  // namespace finseg
