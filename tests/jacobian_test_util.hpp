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

}  // namespace finseg::test
