// One backward-Euler step through the implicit solver's Newton iteration, for tests.
#pragma once

#include "solvers/dofs.hpp"
#include "solvers/implicit_newton.hpp"

namespace finseg::test {

/// One backward-Euler step of h from `start`: the end velocity, the end state in `end`.
struct Step {
  Eigen::VectorXd v;
  State end;
  SolverStats stats;
  bool converged = false;
};

/// The step with at most 50 Newton iterations to `pose_tol` (m and rad); `reuse`: the kept
/// matrix (null: full Newton).
inline Step backward_euler(const Model& model, const State& start, double h, double pose_tol,
                           NewtonReuse* reuse) {
  Step s;
  s.v = velocity_vector(model, start);
  BodyForces f;
  s.converged = backward_euler_solve(model, start, h, 50, pose_tol, s.v, s.end, f, s.stats, reuse);
  return s;
}

}  // namespace finseg::test
