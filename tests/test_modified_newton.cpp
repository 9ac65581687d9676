// Modified Newton (the iteration matrix kept across iterations and steps, docs/solvers.md):
// it reaches full Newton's solution to the Newton tolerance, keeps the matrix where it
// contracts, and makes a new one where a contact switches on and the kept one stops
// contracting.
#include <gtest/gtest.h>

#include <cmath>

#include "collision/contact_laws.hpp"
#include "contact_test_util.hpp"
#include "generators/cantilever.hpp"
#include "newton_test_util.hpp"
#include "solvers/dofs.hpp"
#include "solvers/implicit_newton.hpp"
#include "solvers/linear_solve.hpp"
#include "validation_cantilever.hpp"

namespace finseg {
namespace modified_newton_test {

using test::backward_euler;
using test::Step;

// The stocky strip of the solver agreement test, clamped, loaded at its tip from rest.
Model loaded_strip() {
  CantileverSpec s = validation::slender_strip(8);
  s.thickness = 1e-2;
  s.tip_force = Vec3(0, 0, -2 * bending_rigidity(s) / (s.length * s.length));
  s.damping_time = 1e-4;
  return build_cantilever_model(s);
}

// Full Newton's first two steps of h from rest.
struct FullSteps {
  Step first, second;
};
FullSteps full_newton_steps(const Model& model, double h, double tol) {
  FullSteps f;
  f.first = backward_euler(model, initial_state(model), h, tol, nullptr);
  f.second = backward_euler(model, f.first.end, h, tol, nullptr);
  return f;
}

// A step that had to make a new matrix: solved by GMRES on the kept factor where Krylov steps
// are on (no factorization), else factored.
void expect_new_matrix(const Step& kept, bool krylov) {
  if (krylov) {
    EXPECT_GE(kept.stats.krylov_steps, 1);
    EXPECT_EQ(kept.stats.factorizations, 0);
  } else {
    EXPECT_GE(kept.stats.factorizations, 1);
    EXPECT_EQ(kept.stats.krylov_steps, 0);
  }
}

TEST(ModifiedNewton, KeptMatrixReachesFullNewtonsStepOnALoadedStrip) {
  const Model model = loaded_strip();
  const double h = 1e-5, tol = 1e-12;  // pose tolerance, m and rad
  NewtonReuse reuse;
  reuse.max_age = 20;
  const State start = initial_state(model);
  // Step 1 makes the matrix.
  const Step full1 = backward_euler(model, start, h, tol, nullptr);
  const Step kept1 = backward_euler(model, start, h, tol, &reuse);
  ASSERT_TRUE(full1.converged && kept1.converged);
  EXPECT_GE(kept1.stats.factorizations, 1);
  EXPECT_LT(h * (kept1.v - full1.v).lpNorm<Eigen::Infinity>(), tol);
  // Step 2 (from full Newton's state) contracts on the kept matrix: no new one.
  const Step full = backward_euler(model, full1.end, h, tol, nullptr);
  const Step kept = backward_euler(model, full1.end, h, tol, &reuse);
  ASSERT_TRUE(full.converged && kept.converged);
  EXPECT_EQ(full.stats.factorizations, full.stats.newton_iterations);
  EXPECT_EQ(kept.stats.factorizations, 0);
  EXPECT_EQ(kept.stats.jacobian_evaluations, 0);
  // Both within the pose tolerance of the exact root: within twice of each other.
  EXPECT_LT(h * (kept.v - full.v).lpNorm<Eigen::Infinity>(), 2 * tol);
}

TEST(ModifiedNewton, MatrixOfFreeFlightIsRenewedWhenContactSwitchesOn) {
  // A 1 g plate falling at 0.1 m/s onto a clamped plate (no gravity), Hertz contact
  // (K = 1e9 N/m^1.5): a free-flight step leaves the matrix M, which cannot stand for the
  // contact stiffness of the next step (h^2 K_eff / m of several), so that step must renew it.
  constexpr double kThick = 2e-4, v0 = 0.1, h = 5e-5;
  Model m;
  m.bodies.push_back(
      test::plate("ground", 1, Vec3(0.1, 0.1, kThick), Vec3::Zero(), Mat3::Identity(), true));
  m.bodies.push_back(
      test::plate("plate", 1e-3, Vec3(0.02, 0.02, kThick), Vec3(0, 0, kThick + 1.5 * v0 * h)));
  m.contact.enabled = true;
  m.contact.stiffness = 1e9;
  m.contact.exponent = 1.5;
  m.contact.damping_depth = 1e-5;
  m.finalize_dofs();
  State start = initial_state(m);
  start.v_W[1] = Vec3(0, 0, -v0);
  const double tol = 1e-12;
  for (bool krylov : {false, true}) {
    NewtonReuse reuse;
    reuse.max_age = 20;
    reuse.krylov = krylov;
    const Step flight = backward_euler(m, start, h, tol, &reuse);
    ASSERT_TRUE(flight.converged);
    ASSERT_GT(flight.end.p_W[1].z(), kThick);  // still in the air
    EXPECT_EQ(flight.stats.factorizations, 1);
    const Step full = backward_euler(m, flight.end, h, tol, nullptr);
    const Step kept = backward_euler(m, flight.end, h, tol, &reuse);
    ASSERT_TRUE(full.converged && kept.converged);
    ASSERT_LT(full.end.p_W[1].z(), kThick);  // in contact
    // The contact adds a stiffness of low rank to M: GMRES preconditioned by M's factor
    // solves the new matrix in a few iterations, and no factorization is needed.
    expect_new_matrix(kept, krylov);
    EXPECT_LT(h * (kept.v - full.v).lpNorm<Eigen::Infinity>(), 2 * tol) << krylov;
  }
}

// After an event (a contact point made or lost, a crease snapped: the time stepper marks the
// kept matrix stale) the next step makes a new matrix even where the kept one would still
// contract; with Krylov steps the kept factor preconditions it, without them it is factored.
TEST(ModifiedNewton, AnEventRenewsTheMatrixWhichTheKeptFactorMayPrecondition) {
  const Model model = loaded_strip();
  const double h = 1e-5, tol = 1e-12;
  const State start = initial_state(model);
  const FullSteps f = full_newton_steps(model, h, tol);
  ASSERT_TRUE(f.first.converged && f.second.converged);
  const Step &full1 = f.first, &full = f.second;
  for (bool krylov : {false, true}) {
    NewtonReuse reuse;
    reuse.max_age = 20;
    reuse.krylov = krylov;
    ASSERT_TRUE(backward_euler(model, start, h, tol, &reuse).converged);
    reuse.stale = true;
    const Step kept = backward_euler(model, full1.end, h, tol, &reuse);
    ASSERT_TRUE(kept.converged) << krylov;
    EXPECT_FALSE(reuse.stale);
    EXPECT_GE(kept.stats.jacobian_evaluations, 1) << krylov;
    expect_new_matrix(kept, krylov);
    EXPECT_LT(h * (kept.v - full.v).lpNorm<Eigen::Infinity>(), 2 * tol) << krylov;
  }
}

// A kept matrix of a nonsymmetric model serves as the factor of its symmetric part (the
// strip's damping makes the model nonsymmetric; its matrix is so up to the rotation
// Jacobian's skew part) and still reaches full Newton's step; no LU is made.
TEST(ModifiedNewton, SymmetricPartOfANearlySymmetricMatrixReachesFullNewtonsStep) {
  const Model model = loaded_strip();
  const double h = 1e-5, tol = 1e-12;
  const FullSteps f = full_newton_steps(model, h, tol);
  ASSERT_TRUE(f.first.converged && f.second.converged);
  const State& moving = f.first.end;  // loaded and moving: the skew part is not zero
  const Step& full = f.second;
  for (const double allowed : {0.0, 1e-3}) {
    NewtonReuse reuse;
    reuse.max_age = 20;
    reuse.approximate_asymmetry = allowed;
    const long lu_before = linear_solve_counters().lu_factorizations;
    const Step kept = backward_euler(model, moving, h, tol, &reuse);
    ASSERT_TRUE(kept.converged) << allowed;
    EXPECT_EQ(reuse.approximate, allowed > 0);
    EXPECT_EQ(linear_solve_counters().lu_factorizations > lu_before, allowed == 0);
    EXPECT_LT(h * (kept.v - full.v).lpNorm<Eigen::Infinity>(), 2 * tol) << allowed;
  }
}

// Where the symmetric part does not contract (a plate sliding on a plate: the friction
// force's derivative along the normal has no transpose partner), the solve goes on with LU
// and still reaches full Newton's step.
TEST(ModifiedNewton, LuTakesOverWhereTheSymmetricPartStopsContracting) {
  constexpr double kG = 9.81, kThick = 2e-4, m = 1e-3, h = 2e-3, tol = 1e-12;
  Model mod;
  mod.gravity_W = Vec3(0, 0, -kG);
  mod.bodies.push_back(
      test::plate("ground", 1, Vec3(0.4, 0.1, kThick), Vec3::Zero(), Mat3::Identity(), true));
  mod.contact = test::continuous_contact(suggest_contact(m, kG, 1e-5), 0.3, 0.3);
  const double delta0 = std::pow(m * kG / mod.contact.stiffness, 1 / mod.contact.exponent);
  mod.bodies.push_back(
      test::plate("block", m, Vec3(0.02, 0.02, kThick), Vec3(0, 0, kThick - delta0)));
  mod.finalize_dofs();
  State start = initial_state(mod);
  start.v_W[1] = Vec3(0.05, 0, 0);
  const Step full = backward_euler(mod, start, h, tol, nullptr);
  ASSERT_TRUE(full.converged);
  NewtonReuse reuse;
  reuse.max_age = 20;
  reuse.approximate_asymmetry = 1;  // every matrix's symmetric part is tried first
  reuse.krylov = false;
  long lu_before = linear_solve_counters().lu_factorizations;
  const Step kept = backward_euler(mod, start, h, tol, &reuse);
  ASSERT_TRUE(kept.converged);
  // The symmetric part's factor, then LU's: not one symmetric part after another.
  EXPECT_GE(kept.stats.factorizations, 2);
  EXPECT_LE(kept.stats.factorizations, full.stats.factorizations + 1);
  EXPECT_GT(linear_solve_counters().lu_factorizations, lu_before);
  EXPECT_FALSE(reuse.approximate);
  EXPECT_LT(h * (kept.v - full.v).lpNorm<Eigen::Infinity>(), 2 * tol);
  // With Krylov steps the symmetric part's factor preconditions GMRES on the whole matrix
  // instead: the same step, one factorization, no LU.
  NewtonReuse krylov;
  krylov.max_age = 20;
  krylov.approximate_asymmetry = 1;
  lu_before = linear_solve_counters().lu_factorizations;
  const Step gmres = backward_euler(mod, start, h, tol, &krylov);
  ASSERT_TRUE(gmres.converged);
  EXPECT_EQ(gmres.stats.factorizations, 1);
  EXPECT_GE(gmres.stats.krylov_steps, 1);
  EXPECT_EQ(linear_solve_counters().lu_factorizations, lu_before);
  EXPECT_LT(h * (gmres.v - full.v).lpNorm<Eigen::Infinity>(), 2 * tol);
}

// The implicit solver's run of the loaded strip from rest to t_end with steps of dt (at
// most), `max_iterations` Newton iterations per step (0: its own).
SolverStats run_loaded_strip(double t_end, double dt, int max_iterations = 0) {
  const Model model = loaded_strip();
  SolverSettings set;
  set.kind = SolverKind::Implicit;
  set.t_end = t_end;
  set.output_interval = t_end;
  set.dt = set.dt_max = dt;
  set.max_iterations = max_iterations;
  State s = initial_state(model);
  return run_solver(model, s, set, [](const State&, const BodyForces&) {});
}

// summary.json's `linear_solves` are the run's own: a second run of the same model counts
// the same, and they hold the Newton matrices' factorizations.
TEST(ModifiedNewton, RunCountsItsOwnSparseSolves) {
  const SolverStats first = run_loaded_strip(2e-4, 1e-5), second = run_loaded_strip(2e-4, 1e-5);
  ASSERT_EQ(first.status, "ok") << first.message;
  EXPECT_GE(first.factorizations, 1);
  EXPECT_GE(first.linear.factorizations, first.factorizations);
  EXPECT_LE(first.linear.lu_factorizations, first.linear.factorizations);
  EXPECT_GE(first.linear.analyses, 1);
  EXPECT_GT(first.linear.factor_s, 0);
  EXPECT_GE(first.linear.total_s, first.linear.factor_s);
  EXPECT_EQ(second.linear.factorizations, first.linear.factorizations);
  EXPECT_EQ(second.linear.lu_factorizations, first.linear.lu_factorizations);
  EXPECT_EQ(second.linear.solves, first.linear.solves);
}

// A step whose Newton iteration fails is rejected and counted as such (summary.json's
// `newton_failures`): two iterations cannot solve the loaded strip's first step of 1 ms
// from rest (the tip swings through many times the pose tolerance), so the driver cuts it.
TEST(ModifiedNewton, StepsWhoseNewtonFailsAreCountedApart) {
  const SolverStats stats = run_loaded_strip(1e-3, 1e-3, 2);
  ASSERT_EQ(stats.status, "ok") << stats.message;
  EXPECT_GE(stats.newton_failures, 1);
  EXPECT_LE(stats.newton_failures, stats.rejected_steps);
}

// Backward Euler starts Newton from the velocity the last step's change, continued, reaches.
// Under a uniform acceleration that is the solution: one Newton iteration a step, but for the
// steps after the start and after each output, where the extrapolation is dropped (so that a
// run resumed there starts the same way) and Newton starts from v_n, one correction of h^2 g
// (2.4e-3 m here) away, far beyond its tolerance (1e-3 of the step tolerance, 1e-5 m). The
// velocity stays backward Euler's, g t, exact for uniform acceleration at any steps.
TEST(ModifiedNewton, BackwardEulerStartsFromTheExtrapolatedVelocity) {
  Model m;
  m.bodies = {test::plate("falling", 1e-3, Vec3(0.01, 0.01, 1e-3), Vec3::Zero())};
  m.gravity_W = Vec3(0, 0, -9.81);
  m.sheet.length = 1;
  m.finalize_dofs();
  State state = initial_state(m);
  SolverSettings s;
  s.kind = SolverKind::Implicit;
  s.t_end = 1;
  s.output_interval = 0.125;
  s.dt = s.dt_max = 1.0 / 64;  // 8 steps an output, binary fractions: no slivers
  s.rtol = 1e-2;               // h/2 |dv| = 1.2e-3 m a step: every step is accepted
  int outputs = 0;
  const SolverStats stats =
      run_solver(m, state, s, [&](const State&, const BodyForces&) { ++outputs; });
  ASSERT_EQ(stats.status, "ok") << stats.message;
  EXPECT_EQ(stats.rejected_steps, 0);
  ASSERT_EQ(stats.steps, 64);
  // Two iterations at the start and after each of the 7 outputs before the end, one else.
  EXPECT_EQ(stats.newton_iterations, stats.steps + 8) << outputs << " outputs";
  EXPECT_NEAR(state.v_W[0].z(), -9.81, 1e-12);
}

}  // namespace modified_newton_test
}  // namespace finseg
