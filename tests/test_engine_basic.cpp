// Basic engine checks against closed-form linear beam theory and exact derivatives.
#include <gtest/gtest.h>

#include "elements/assemble.hpp"
#include "generators/sheet.hpp"
#include "jacobian_test_util.hpp"
#include "solvers/dofs.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace engine_basic_test {

SheetSpec strip(int n) {
  SheetSpec s;
  s.length = 0.1;
  s.width = 0.01;
  s.thickness = 1e-3;
  s.youngs_modulus = 2e9;
  s.poisson_ratio = 0.3;
  s.density = 1000;
  s.cells_along = n;
  s.clamp_start = true;
  return s;
}

double bending_rigidity(const SheetSpec& s) {
  return s.youngs_modulus * s.width * s.thickness * s.thickness * s.thickness / 12.0;
}

TEST(EngineBasic, SmallTipLoadMatchesLinearBeam) {
  const SheetSpec s = strip(32);
  Model m = build_sheet_model(s);
  const MaterialPoint tip = locate_material_point(m, s.length, 0.5 * s.width);
  const double EI = bending_rigidity(s);
  const double P = 1e-4 * EI / (s.length * s.length);  // alpha = 1e-4: linear regime
  m.loads.push_back({tip.body, tip.r_B, Vec3(0, 0, -P), Vec3::Zero(), false});
  State st = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Static;
  const SolverStats stats = run_solver(m, st, set, {});
  ASSERT_EQ(stats.status, "ok") << stats.message;
  const Vec3 p = st.p_W[tip.body] + st.R_WB[tip.body] * tip.r_B;
  const double beam = P * std::pow(s.length, 3) / (3 * EI);
  const double shear = P * s.length / (5.0 / 6.0 * s.youngs_modulus / 2.6 * s.width * s.thickness);
  EXPECT_NEAR(-p.z() / (beam + shear), 1.0, 2e-3);
}

TEST(EngineBasic, JacobianMatchesFiniteDifferences) {
  SheetSpec s = strip(4);
  s.cells_across = 2;
  s.damping_time = 1e-3;
  Model m = build_sheet_model(s);
  State st = initial_state(m);
  // A generic deformed, moving configuration.
  Eigen::VectorXd dq(m.num_dofs), v(m.num_dofs);
  for (int i = 0; i < m.num_dofs; ++i) {
    dq[i] = 1e-3 * std::sin(1.3 * i + 0.2);
    v[i] = 0.1 * std::cos(0.7 * i);
  }
  apply_pose_increment(m, st, dq);
  set_velocity(m, st, v);
  BodyForces f;
  ForceJacobian jac;
  compute_forces(m, st, f, &jac);
  const Eigen::MatrixXd Jq = jac.dq, Jv = jac.dv;
  const double h = 1e-7;
  for (int c = 0; c < m.num_dofs; ++c) {
    const Eigen::VectorXd fd = test::fd_pose_column(m, st, c, h);
    EXPECT_LE((fd - Jq.col(c)).norm(), 1e-5 * (1 + Jq.col(c).norm())) << "column " << c;
    const Eigen::VectorXd fdv = test::fd_velocity_column(m, st, v, c, h);
    EXPECT_LE((fdv - Jv.col(c)).norm(), 1e-5 * (1 + Jv.col(c).norm())) << "column " << c;
  }
}

TEST(EngineBasic, ForcesAreMinusEnergyGradient) {
  SheetSpec s = strip(3);
  s.cells_across = 2;
  Model m = build_sheet_model(s);
  State st = initial_state(m);
  Eigen::VectorXd dq(m.num_dofs);
  for (int i = 0; i < m.num_dofs; ++i) dq[i] = 2e-2 * std::sin(2.1 * i + 0.5);
  apply_pose_increment(m, st, dq);
  BodyForces f;
  compute_forces(m, st, f);
  const Eigen::VectorXd g = generalized_forces(m, f);
  const double h = 1e-6;
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
    EXPECT_NEAR(-dU, g[c], 1e-5 * (1 + std::abs(g[c]))) << "dof " << c;
  }
}

}  // namespace engine_basic_test
}  // namespace finseg
