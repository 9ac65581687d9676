// The static solver converges in tens of Newton iterations from the flat state at any
// resolution (issue 12 item 2): the end-loaded cantilever (alpha = 2) against the elastica,
// the strip under its own weight, and follower loads (an end moment that rolls the strip into
// a circle; an end force that stays normal to the tip). References: elastica_reference.hpp
// (elliptic integrals, circular arc) and second-order convergence under refinement.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/so3.hpp"
#include "elastica_reference.hpp"
#include "generators/sheet.hpp"
#include "solvers/linear_solve.hpp"
#include "validation_cantilever.hpp"

namespace finseg {
namespace static_solver_test {

using validation::probe_position;
using validation::slender_strip;

constexpr long kMaxIterations = 40;  // the bound, at every resolution

struct StaticResult {
  SolverStats stats;
  Vec3 tip_over_L;  // tip displacement from its undeformed place, / L
};

StaticResult solve(const CantileverSpec& spec, bool follower = false) {
  Model m = build_cantilever_model(spec);
  for (LoadDef& l : m.loads) l.follower = follower;
  State s = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Static;
  StaticResult r;
  r.stats = run_solver(m, s, set, {});
  EXPECT_EQ(r.stats.status, "ok") << r.stats.message;
  r.tip_over_L =
      (probe_position(m, s, "tip") - Vec3(spec.length, 0.5 * spec.width, 0)) / spec.length;
  return r;
}

// Formerly about 610 iterations at every resolution (four full-load attempts cut).
TEST(StaticSolver, EndLoadedCantileverInFewIterationsAtEveryResolution) {
  const reference::ElasticaTip ref = reference::elastica_tip_load(2.0);
  for (int n : {16, 64, 256, 1024}) {
    CantileverSpec s = slender_strip(n);
    s.tip_force = Vec3(0, 0, -2.0 * bending_rigidity(s) / (s.length * s.length));
    const StaticResult r = solve(s);
    EXPECT_LE(r.stats.newton_iterations, kMaxIterations) << n << " segments";
    if (n >= 64) {  // the discretisation error is below 0.5 % from 64 segments on
      EXPECT_NEAR(-r.tip_over_L.x() / ref.horizontal, 1.0, 5e-3) << n << " segments";
      EXPECT_NEAR(-r.tip_over_L.z() / ref.vertical, 1.0, 5e-3) << n << " segments";
    }
  }
}

// The 200 x 40 x 0.1 mm paper strip under its own weight, q L^3 / (E I) = 18.8: formerly
// 1 844-2 070 iterations. No closed form: the tip converges at second order instead.
TEST(StaticSolver, SelfWeightStripInFewIterationsAndSecondOrder) {
  std::vector<Vec3> tips;
  for (int n : {16, 64, 256, 1024}) {
    CantileverSpec s = slender_strip(n);
    s.length = 0.2;
    s.width = 0.04;
    s.gravity = true;
    const double q = s.density * s.width * s.thickness * 9.81;
    ASSERT_NEAR(q * std::pow(s.length, 3) / bending_rigidity(s), 18.8, 0.05);
    const StaticResult r = solve(s);
    EXPECT_LE(r.stats.newton_iterations, kMaxIterations) << n << " segments";
    tips.push_back(r.tip_over_L);
  }
  // Each refinement by 4 divides the error by 16 at second order.
  const double e1 = (tips[1] - tips[2]).norm(), e2 = (tips[2] - tips[3]).norm();
  EXPECT_NEAR(std::log(e1 / e2) / std::log(4.0), 2.0, 0.2) << e1 << " " << e2;
  EXPECT_GT(-tips[3].z(), 0.5);  // a large deflection, not a nearly linear one
}

// A follower end moment M bends the strip into a circular arc of curvature M / (E I) exactly
// (the moment is the same at every section whatever the shape): a quarter circle and a full
// circle whose tip returns to the clamp.
TEST(StaticSolver, FollowerEndMomentRollsTheStripIntoAnArc) {
  for (double turn : {0.5 * std::numbers::pi, 2 * std::numbers::pi}) {
    CantileverSpec s = slender_strip(64);
    s.tip_moment = Vec3(0, -turn * bending_rigidity(s) / s.length, 0);  // tip bends towards +z
    const StaticResult r = solve(s, true);
    const reference::ArcTip ref = reference::arc_tip(turn);
    EXPECT_LE(r.stats.newton_iterations, kMaxIterations) << turn << " rad";
    EXPECT_NEAR(1 + r.tip_over_L.x(), ref.along, 1e-3) << turn << " rad";
    EXPECT_NEAR(r.tip_over_L.z(), ref.across, 1e-3) << turn << " rad";
  }
}

// A follower end force that stays normal to the tip (F L^2 / (E I) = 2; formerly the solver
// did not finish, > 180 s at 8 segments): few iterations at every resolution and the tip
// converging at second order.
TEST(StaticSolver, FollowerEndForceConvergesInFewIterations) {
  std::vector<Vec3> tips;
  for (int n : {16, 32, 64, 256}) {
    CantileverSpec s = slender_strip(n);
    s.tip_force = Vec3(0, 0, -2.0 * bending_rigidity(s) / (s.length * s.length));
    const StaticResult r = solve(s, true);
    EXPECT_LE(r.stats.newton_iterations, kMaxIterations) << n << " segments";
    tips.push_back(r.tip_over_L);
  }
  const double e1 = (tips[0] - tips[1]).norm(), e2 = (tips[1] - tips[2]).norm();
  EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.2) << e1 << " " << e2;
  // It sags further than the dead load of the same size: turning with the tip, the force
  // keeps its whole lever.
  const reference::ElasticaTip dead = reference::elastica_tip_load(2.0);
  EXPECT_GT(-tips[3].z(), dead.vertical);
}

// A 200 x 200 x 1 mm sheet of 8 x 8 segments clamped along x = 0, under its own weight
// (q L^3 / (E I) = 0.19) and a dead force of half its weight at a free corner that twists it
// (both conservative): 17 mm at the corner, within reach of plain Newton from the flat state.
Model twisted_sheet() {
  SheetSpec spec;
  spec.length = spec.width = 0.2;
  spec.thickness = 1e-3;
  spec.cells_along = spec.cells_across = 8;
  spec.clamp_start = true;
  Model m = build_sheet_model(spec);
  m.gravity_W = Vec3(0, 0, -9.81);
  double weight = 0;
  for (const BodyDef& b : m.bodies) weight += 9.81 * b.mass;
  LoadDef corner;
  corner.body = locate_material_point(m, 0.2, 0.2).body;
  corner.point_B = locate_material_point(m, 0.2, 0.2).r_B;
  corner.force = Vec3(0, 0, -0.5 * weight);
  m.loads.push_back(corner);
  return m;
}

// A state off equilibrium: the corner force's twist w = c x y with its rotations, no sag.
State twisted_state(const Model& m) {
  State state = initial_state(m);
  constexpr double c = 0.5;  // 1/m: 20 mm at the free corner
  Eigen::VectorXd dq = Eigen::VectorXd::Zero(m.num_dofs);
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const int d = m.dof_of_body[i];
    if (d < 0) continue;
    const double x = m.bodies[i].p0_W.x(), y = m.bodies[i].p0_W.y();
    dq[d + 2] = c * x * y;
    dq[d + 3] = c * x;   // dw/dy
    dq[d + 4] = -c * y;  // -dw/dx
  }
  apply_pose_increment(m, state, dq);
  return state;
}

// The exact stiffness of a conservative model, K = -dq with the left-trivialised rotation
// perturbation R = exp([dphi]x) R, is the Hessian of the energy in the exponential chart plus
// the skew term (1/2)[tau_i]x in body i's rotation block (second order of exp(a) exp(b) =
// exp(a + b + a x b / 2 + ...)), tau_i the out-of-balance torque on the body. So K - K^T is
// [tau_i]x on the diagonal blocks and zero elsewhere; the torques here are far above
// round-off (the state is off equilibrium).
TEST(StaticSolver, ConservativeStiffnessIsSymmetricButForTheOutOfBalanceTorques) {
  const Model m = twisted_sheet();
  ASSERT_TRUE(conservative_stiffness(m));
  const State state = twisted_state(m);
  BodyForces f;
  ForceJacobian jac;
  jac.with_velocity = false;
  compute_forces(m, state, f, &jac);
  const Eigen::SparseMatrix<double> K = -jac.dq;
  Eigen::SparseMatrix<double> skew = K - Eigen::SparseMatrix<double>(K.transpose());
  double tau_max = 0;
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const int d = m.dof_of_body[i];
    if (d < 0) continue;
    const Mat3 T = hat<double>(f.tau_W[i]);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) skew.coeffRef(d + 3 + r, d + 3 + c) -= T(r, c);
    }
    tau_max = std::max(tau_max, f.tau_W[i].norm());
  }
  const double K_max = Eigen::MatrixXd(K).cwiseAbs().maxCoeff();
  EXPECT_GT(asymmetry_ratio(K), 1e3 * kSymmetricAsymmetry);  // not symmetric as it stands
  EXPECT_GT(tau_max, 1e6 * 1e-16 * K_max);
  EXPECT_LT(Eigen::MatrixXd(skew).cwiseAbs().maxCoeff(), 1e-12 * K_max);
}

// Plain Newton (no line search) from the flat state of the twisted sheet, with the exact
// stiffness (LU) or its symmetric part (Cholesky). The dropped term is proportional to the
// residual, so both converge quadratically: the same number of iterations (within one) and
// the same equilibrium (measured: 6 and 6 iterations, 1e-14 m apart; with the sheet 0.5 mm
// thick, 14 and 16).
struct PlainNewton {
  int iterations = 0;
  bool converged = false;
  State state;
  bool used_lu = false, used_cholesky = false;
};

PlainNewton plain_newton(const Model& m, bool symmetric) {
  double weight = 0;
  for (const BodyDef& b : m.bodies) weight += 9.81 * b.mass;
  PlainNewton run;
  run.state = initial_state(m);
  BodyForces f;
  ForceJacobian jac;
  jac.with_velocity = false;
  for (run.iterations = 0; run.iterations < 30; ++run.iterations) {
    compute_forces(m, run.state, f, &jac);
    const Eigen::VectorXd g = generalized_forces(m, f);
    // Forces in N, torques in N m (L = 0.2 m); round-off in the stiff in-plane springs leaves
    // residuals of about 5e-10 of the weight.
    if (g.lpNorm<Eigen::Infinity>() <= 1e-8 * weight) {
      run.converged = true;
      return run;
    }
    const Eigen::SparseMatrix<double> K = -jac.dq;
    Eigen::VectorXd dq;
    LinearSolveInfo info;
    if (!sparse_solve(symmetric ? symmetric_part(K) : K, g, dq, &info)) return run;
    (info.path == LinearSolvePath::LU ? run.used_lu : run.used_cholesky) = true;
    apply_pose_increment(m, run.state, dq);
  }
  return run;
}

TEST(StaticSolver, SymmetricNewtonMatrixConvergesAsTheExactOneOffEquilibrium) {
  const Model m = twisted_sheet();
  const PlainNewton exact = plain_newton(m, false), symmetric = plain_newton(m, true);
  ASSERT_TRUE(exact.converged);
  ASSERT_TRUE(symmetric.converged);
  EXPECT_TRUE(exact.used_lu);  // off equilibrium, the exact stiffness is not symmetric
  EXPECT_FALSE(symmetric.used_lu);
  EXPECT_TRUE(symmetric.used_cholesky);
  EXPECT_LE(std::abs(symmetric.iterations - exact.iterations), 1)
      << symmetric.iterations << " vs " << exact.iterations;
  double dp = 0, sag = 0;
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    dp = std::max(dp, (symmetric.state.p_W[i] - exact.state.p_W[i]).norm());
    sag = std::max(sag, (exact.state.p_W[i] - m.bodies[i].p0_W).norm());
  }
  EXPECT_GT(sag, 0.01);  // a large deflection, 5 % of the length at least
  EXPECT_LT(dp, 1e-9 * sag);
}

}  // namespace static_solver_test
}  // namespace finseg
