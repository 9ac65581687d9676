// The static solver through indefinite iterates: a square paper sheet clamped along one edge
// sagging under its own weight from the flat state (bench/bench_sheet_scale.cpp's case, 16 x 16
// segments) meets Newton matrices that are not positive definite on its way (the straight-line
// rotation steps leave it unstable), which the solver shifts (Levenberg-Marquardt). References:
// the equilibrium is a stable one (its stiffness positive definite: a cantilevered plate under
// self-weight does not buckle), and it is the one load stepping reaches through other iterates.
#include <gtest/gtest.h>

#include "elements/assemble.hpp"
#include "generators/sheet.hpp"
#include "solvers/linear_solve.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace static_sheet_test {

SolverStats solve(const Model& m, State& s, int load_steps) {
  SolverSettings set;
  set.kind = SolverKind::Static;
  set.load_steps = load_steps;
  return run_solver(m, s, set, {});
}

TEST(StaticSheet, SelfWeightThroughIndefiniteIteratesToAStableEquilibrium) {
  const Model m = clamped_paper_sheet(16);
  State s = initial_state(m);
  linear_solve_counters() = {};
  const SolverStats st = solve(m, s, 1);
  ASSERT_EQ(st.status, "ok") << st.message;
  EXPECT_GT(linear_solve_counters().indefinite, 0);  // the case exercises the shift
  // The plate's Poisson coupling meets the membrane in this thin sheet (Searle's b^2 kappa / t
  // ~ 80 already at 1 % of the load): from flat with the cell corrections on, Newton took 134
  // iterations; the loads stepped without them and the corrections switched on after, 21
  // (docs/solvers.md, "Plates: the corrections last"). The bound is the shifted Newton's of
  // the rows of beam joints (16 iterations then).
  EXPECT_LE(st.newton_iterations, 40);
  EXPECT_EQ(s.plate_correction_scale, 1.0);  // the equilibrium is the whole model's
  EXPECT_EQ(linear_solve_counters().lu_factorizations, 0);

  ForceJacobian jac;
  jac.with_velocity = false;
  BodyForces f;
  compute_forces(m, s, f, &jac);
  Eigen::VectorXd x;
  EXPECT_EQ(cholesky_solve(SymmetricMatrix::symmetric_part_of(-jac.dq),
                           Eigen::VectorXd::Ones(m.num_dofs), x),
            CholeskyStatus::Solved);

  State stepped = initial_state(m);
  ASSERT_EQ(solve(m, stepped, 8).status, "ok");
  double dp = 0;
  for (size_t i = 0; i < m.bodies.size(); ++i)
    dp = std::max(dp, (s.p_W[i] - stepped.p_W[i]).norm());
  EXPECT_LT(dp, 1e-7 * 0.2);  // the solver's tolerance level, of the sheet's length
  double z_min = 0;
  for (const Vec3& p : s.p_W) z_min = std::min(z_min, p.z());
  EXPECT_LT(z_min, -0.5 * 0.2);  // a large deflection (q L^3 / (E I) = 18.8)
}

}  // namespace static_sheet_test
}  // namespace finseg
