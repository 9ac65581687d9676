// Central differences of the generalized forces, the oracle the Jacobian tests compare with.
#pragma once

#include <Eigen/Dense>

#include "elements/assemble.hpp"
#include "solvers/dofs.hpp"

namespace finseg::test {

/// Column c of d(generalized force)/d(pose perturbation) at `st`, by a central difference
/// of step h (m or rad).
inline Eigen::VectorXd fd_pose_column(const Model& m, const State& st, int c, double h) {
  Eigen::VectorXd e = Eigen::VectorXd::Zero(m.num_dofs);
  e[c] = h;
  State a = st, b = st;
  apply_pose_increment(m, a, e);
  apply_pose_increment(m, b, -e);
  BodyForces fa, fb;
  compute_forces(m, a, fa);
  compute_forces(m, b, fb);
  return (generalized_forces(m, fa) - generalized_forces(m, fb)) / (2 * h);
}

/// Column c of d(generalized force)/d(velocity) at `st` with velocity vector v, step h (m/s
/// or rad/s).
inline Eigen::VectorXd fd_velocity_column(const Model& m, const State& st, const Eigen::VectorXd& v,
                                          int c, double h) {
  Eigen::VectorXd e = Eigen::VectorXd::Zero(m.num_dofs);
  e[c] = h;
  State a = st, b = st;
  set_velocity(m, a, v + e);
  set_velocity(m, b, v - e);
  BodyForces fa, fb;
  compute_forces(m, a, fa);
  compute_forces(m, b, fb);
  return (generalized_forces(m, fa) - generalized_forces(m, fb)) / (2 * h);
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
