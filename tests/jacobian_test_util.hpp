// Central differences of the generalized forces, the oracle the Jacobian tests compare with.
#pragma once

#include <Eigen/Dense>

#include "elements/assemble.hpp"
#include "solvers/dofs.hpp"
#include "solvers/force_check.hpp"

namespace finseg::test {

/// Column c of d(generalized force)/d(pose perturbation) at `st`, by a central difference
/// of step h (m or rad).
inline Eigen::VectorXd fd_pose_column(const Model& m, const State& st, int c, double h) {
  return force_difference(m, st, c, h, false);
}

/// Column c of d(generalized force)/d(velocity) at `st` with velocity vector v, step h (m/s
/// or rad/s).
inline Eigen::VectorXd fd_velocity_column(const Model& m, const State& st, const Eigen::VectorXd& v,
                                          int c, double h) {
  State at = st;
  set_velocity(m, at, v);
  return force_difference(m, at, c, h, true);
}

/// The Jacobian of the generalized forces by pose (dense), as the solvers assemble it.
inline Eigen::MatrixXd pose_jacobian(const Model& m, const State& st) {
  BodyForces f;
  ForceJacobian jac;
  jac.with_velocity = false;
  compute_forces(m, st, f, &jac);
  return Eigen::MatrixXd(jac.dq);
}

/// The same by central differences of step h (m or rad), column by column.
inline Eigen::MatrixXd fd_pose_jacobian(const Model& m, const State& st, double h) {
  Eigen::MatrixXd J(m.num_dofs, m.num_dofs);
  for (int c = 0; c < m.num_dofs; ++c) J.col(c) = fd_pose_column(m, st, c, h);
  return J;
}

}  // namespace finseg::test
