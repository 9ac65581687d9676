// Continuous friction in Newton's iteration matrix (docs/solvers.md, "Friction's secant"): the
// slopes the secant takes against the law's closed form, and a step in which twelve plates stop
// or slide on at once against Coulomb's law for one backward Euler step (v1 = v0 - h mu g
// v0 / |v0| where that stays ahead, rest within the law's stick band where it does not), with
// full and with modified Newton; and a solve that goes on with the secant stops within Newton's
// tolerance of the root. The cone whose steps collapsed without the secant is
// tests/test_cone_friction.cpp.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/SparseLU>
#include <cmath>
#include <vector>

#include "collision/contact_laws.hpp"
#include "contact_test_util.hpp"
#include "newton_test_util.hpp"
#include "solvers/dofs.hpp"
#include "solvers/implicit_newton.hpp"

namespace finseg {
namespace friction_secant_test {

ContactDef friction_law() {
  ContactDef c;
  c.enabled = true;
  c.friction = FrictionModel::Continuous;
  c.mu_static = 0.3;
  c.mu_dynamic = 0.25;
  c.stiction_speed = 1e-4;
  c.friction_speed = 1e-3;
  return c;
}

// On the plateau the tangent has no slope along the slip and fn mu_s / v across it; the
// secant has fn mu_s / v in both (mu(v) / v, a chord through the origin).
TEST(FrictionSecant, SlopesOnThePlateauAreTheChordThroughTheOrigin) {
  const ContactDef c = friction_law();
  const double fn = 2.0, v = 5e-3, lag = 0;  // lagged: the rising part only
  const Vec3 v_t(0.6 * v, 0.8 * v, 0), along = v_t / v, across(-0.8, 0.6, 0);
  const FrictionSlopes tangent = continuous_friction_slopes(c, fn, v_t, lag);
  const FrictionSlopes secant = continuous_friction_slopes(c, fn, v_t, lag, FrictionSlope::Secant);
  EXPECT_FALSE(tangent.secant_differs);
  EXPECT_TRUE(secant.secant_differs);
  EXPECT_NEAR(along.dot(tangent.d_vt * along), 0, 1e-12);
  EXPECT_NEAR(across.dot(tangent.d_vt * across), -fn * c.mu_static / v, 1e-9);
  EXPECT_NEAR(along.dot(secant.d_vt * along), -fn * c.mu_static / v, 1e-9);
  EXPECT_NEAR(across.dot(secant.d_vt * across), -fn * c.mu_static / v, 1e-9);
  EXPECT_EQ((secant.f - tangent.f).norm(), 0);  // the force is the law's either way
  EXPECT_EQ((secant.d_fn - tangent.d_fn).norm(), 0);
}

// Inside the stick band, near v = 0, the two agree to O(v^2): mu(v) / v and mu'(v) both tend
// to 3 mu_s / (2 v_s).
TEST(FrictionSecant, SlopesAgreeAtRest) {
  const ContactDef c = friction_law();
  const double fn = 2.0, v = 1e-3 * c.stiction_speed;
  const Vec3 v_t(v, 0, 0);
  const FrictionSlopes tangent = continuous_friction_slopes(c, fn, v_t, 0);
  const FrictionSlopes secant = continuous_friction_slopes(c, fn, v_t, 0, FrictionSlope::Secant);
  const double stick = -fn * 1.5 * c.mu_static / c.stiction_speed;
  EXPECT_NEAR(tangent.d_vt(0, 0), stick, 1e-5 * std::abs(stick));
  EXPECT_NEAR(secant.d_vt(0, 0), stick, 1e-5 * std::abs(stick));
}

constexpr double kG = 9.81, kThick = 2e-4, kMass = 1e-3, kH = 2e-3, kMu = 0.3;

// Twelve 1 g plates resting on one clamped plate, thrown in twelve directions at speeds
// between 0.3 and 2 times h mu g (the speed friction takes away in one step): the ones below
// stop within the step, the others slide on.
struct Scattered {
  Model model;
  State start;
  std::vector<double> speed_ratio;
};

// A clamped plate under gravity with continuous friction mu_s = mu_d = kMu, its contact
// suggested for `load` kg resting on it.
Model ground(double load) {
  Model m;
  m.gravity_W = Vec3(0, 0, -kG);
  m.bodies.push_back(
      test::plate("ground", 1, Vec3(0.6, 0.2, kThick), Vec3::Zero(), Mat3::Identity(), true));
  m.contact = test::continuous_contact(suggest_contact(load, kG, 1e-5), kMu, kMu);
  return m;
}

Scattered scattered_plates() {
  Scattered s;
  s.model = ground(kMass);
  Model& m = s.model;
  const double delta0 = std::pow(kMass * kG / m.contact.stiffness, 1 / m.contact.exponent);
  s.speed_ratio = {0.3, 1.3, 0.55, 2.0, 0.8, 1.6, 0.95, 1.1, 0.4, 1.8, 0.7, 1.45};
  for (std::size_t k = 0; k < s.speed_ratio.size(); ++k) {
    const Vec3 p(-0.25 + 0.045 * static_cast<double>(k), 0, kThick - delta0);
    m.bodies.push_back(test::plate(fmt::format("plate{}", k), kMass, Vec3(0.02, 0.02, kThick), p));
  }
  m.finalize_dofs();
  s.start = initial_state(m);
  const double c = kH * kMu * kG;
  for (std::size_t k = 0; k < s.speed_ratio.size(); ++k) {
    const double a = 0.5236 * static_cast<double>(k);  // 30 degrees apart
    s.start.v_W[k + 1] = s.speed_ratio[k] * c * Vec3(std::cos(a), std::sin(a), 0);
  }
  return s;
}

void expect_coulomb(const Scattered& s, const State& end) {
  const ContactDef& law = s.model.contact;
  const double c = kH * kMu * kG;
  for (std::size_t k = 0; k < s.speed_ratio.size(); ++k) {
    SCOPED_TRACE(k);
    const Vec3& v0 = s.start.v_W[k + 1];
    const Vec3& v1 = end.v_W[k + 1];
    if (s.speed_ratio[k] < 1) {
      EXPECT_LT(v1.norm(), law.stiction_speed);  // at rest, up to the law's creep
    } else {
      const Vec3 coulomb = v0 - c * v0.normalized();
      EXPECT_LT((v1 - coulomb).norm(), 1e-3 * coulomb.norm());
    }
  }
}

// Full Newton (a new matrix every iteration) and the solvers' default, matrices kept.
TEST(FrictionSecant, ManyPlatesStoppingOrSlidingInOneStepMeetCoulomb) {
  for (const int max_age : {1, 20}) {
    SCOPED_TRACE(max_age);
    const Scattered s = scattered_plates();
    NewtonReuse reuse;
    reuse.max_age = max_age;
    const test::Step step = test::backward_euler(s.model, s.start, kH, 1e-12, &reuse);
    ASSERT_TRUE(step.converged);
    expect_coulomb(s, step.end);
  }
}

// Two plates stacked on a clamped one, thrown and spun against each other: a step in which
// the tangent's halvings lower nothing, so the solve goes on with the secant, and stops on the
// contraction bound. The exact Newton correction at the point it returns (tangent matrix, one
// LU solve) must be below the pose tolerance too: the secant leaves no more error than
// Newton's test would.
Model stack_of_two() {
  Model m = ground(2 * kMass);
  for (int k = 0; k < 2; ++k) {
    const Vec3 p(0.001 * k, 0.0007 * k, kThick * (k + 1) - 1e-6 * (k + 1));
    m.bodies.push_back(
        test::plate(fmt::format("layer{}", k), kMass, Vec3(0.02 + 0.002 * k, 0.02, kThick), p));
  }
  m.finalize_dofs();
  return m;
}

TEST(FrictionSecant, SolveStoppedOnTheSecantIsWithinNewtonsTolerance) {
  const Model m = stack_of_two();
  State start = initial_state(m);
  const double c = 0.3 * kH * kMu * kG;  // 0.3 of the speed friction takes in a step
  for (int k = 0; k < 2; ++k) {
    start.v_W[k + 1] = c * Vec3(std::cos(2.1 * k), std::sin(2.1 * k), 0);
    start.w_W[k + 1] = Vec3(0, 0, (k == 0 ? -1 : 1) * c / 0.01);
  }
  constexpr double kTol = 1e-9;  // m and rad
  for (const int max_age : {1, 20}) {
    SCOPED_TRACE(max_age);
    NewtonReuse reuse;
    reuse.max_age = max_age;
    const test::Step step = test::backward_euler(m, start, kH, kTol, &reuse);
    ASSERT_TRUE(step.converged);
    EXPECT_EQ(step.stats.secant_solves, 1);
    AffineStep map;
    map.dq0 = map.v0 = Eigen::VectorXd::Zero(m.num_dofs);
    map.cq = kH;
    map.cv = 1;
    NewtonResidual res;
    res.b = momentum(m, start);
    res.s = kH;
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> A;
    State at;
    newton_linearisation(m, start, kH, map, res, step.v, at, r, A);
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(A);
    ASSERT_EQ(lu.info(), Eigen::Success);
    const Eigen::VectorXd dx = lu.solve(-r);
    EXPECT_LT(kH * dx.lpNorm<Eigen::Infinity>(), kTol);
  }
}

}  // namespace friction_secant_test

}  // namespace finseg
