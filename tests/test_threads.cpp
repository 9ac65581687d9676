// Results do not depend on the number of threads (issue 12 item 5): the force elements run
// in parallel, each writing its own slots, and are summed in element order.
#include <gtest/gtest.h>
#include <omp.h>

#include "core/threads.hpp"
#include "elements/assemble.hpp"
#include "elements/force_elements.hpp"
#include "generators/sheet.hpp"
#include "solvers/dofs.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace threads_test {

// A damped plate large enough for the parallel loop (over 512 elements).
Model plate() {
  SheetSpec s;
  s.length = 0.2;
  s.width = 0.1;
  s.thickness = 1e-4;
  s.youngs_modulus = 4e9;
  s.poisson_ratio = 0.3;
  s.density = 800;
  s.cells_along = 24;
  s.cells_across = 12;
  s.clamp_start = true;
  s.damping_time = 1e-3;
  return build_sheet_model(s);
}

State moving_state(const Model& m) {
  State st = initial_state(m);
  Eigen::VectorXd dq(m.num_dofs), v(m.num_dofs);
  for (int i = 0; i < m.num_dofs; ++i) {
    dq[i] = 0.01 * std::sin(0.37 * i) * ((i % 6) < 3 ? 1e-2 : 1.0);
    v[i] = 0.1 * std::cos(0.7 * i);
  }
  apply_pose_increment(m, st, dq);
  set_velocity(m, st, v);
  return st;
}

struct Evaluation {
  BodyForces f;
  ForceJacobian jac;
};

Evaluation evaluate(const Model& m, const State& st, int threads) {
  omp_set_num_threads(threads);
  Evaluation e;
  compute_forces(m, st, e.f, &e.jac);
  return e;
}

bool same_bits(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& b) {
  return a.nonZeros() == b.nonZeros() &&
         std::equal(a.valuePtr(), a.valuePtr() + a.nonZeros(), b.valuePtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr());
}

TEST(Threads, ForcesAndJacobianAreBitIdenticalForOneTwoAndFourThreads) {
  const Model m = plate();
  ASSERT_GT(m.elements.size(), 512u);
  const State st = moving_state(m);
  const int saved = omp_get_max_threads();
  const Evaluation one = evaluate(m, st, 1);
  for (const int threads : {2, 4}) {
    const Evaluation many = evaluate(m, st, threads);
    EXPECT_EQ(one.f.potential_energy, many.f.potential_energy);
    EXPECT_EQ(one.f.f_W, many.f.f_W);
    EXPECT_EQ(one.f.tau_W, many.f.tau_W);
    EXPECT_TRUE(same_bits(one.jac.dq, many.jac.dq)) << threads << " threads";
    EXPECT_TRUE(same_bits(one.jac.dv, many.jac.dv)) << threads << " threads";
  }
  omp_set_num_threads(saved);
}

TEST(Threads, StaticSolveEndsInTheSameStateOnOneAndTwoThreads) {
  Model m = plate();
  m.gravity_W = Vec3(0, 0, -9.81);
  const int saved = omp_get_max_threads();
  std::vector<State> ends;
  for (const int threads : {1, 2}) {
    omp_set_num_threads(threads);
    State st = initial_state(m);
    SolverSettings set;
    set.kind = SolverKind::Static;
    ASSERT_EQ(run_solver(m, st, set, {}).status, "ok");
    ends.push_back(st);
  }
  omp_set_num_threads(saved);
  EXPECT_EQ(ends[0].p_W, ends[1].p_W);
  EXPECT_EQ(ends[0].R_WB, ends[1].R_WB);
}

// The team of a region that asks for 4 threads whatever the setting, as CHOLMOD's do.
int team_of_four() {
  int team = 0;
#pragma omp parallel num_threads(4)
  {
#pragma omp single
    team = omp_get_num_threads();
  }
  return team;
}

TEST(Threads, OneThreadKeepsALibrarysFourThreadRegionOnOneThread) {
  const int saved = thread_count();
  set_thread_count(1);
  EXPECT_EQ(thread_count(), 1);
  EXPECT_EQ(team_of_four(), 1);
  set_thread_count(2);  // and back: parallel again
  EXPECT_EQ(thread_count(), 2);
  EXPECT_EQ(team_of_four(), 4);
  set_thread_count(saved);
}

}  // namespace threads_test
}  // namespace finseg
