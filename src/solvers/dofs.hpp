// Helpers shared by the solvers: moving between State and DOF vectors, mass matrices,
// energies and the divergence diagnosis.
#pragma once

#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "elements/assemble.hpp"
#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// Applies a pose increment: p_W += dq[0:3], R_WB = exp([dq[3:6]]x) R_WB per free body.
void apply_pose_increment(const Model& model, State& state, const Eigen::VectorXd& dq);

/// One 3 x 3 block per body (bodies without DOFs hold unused blocks).
using RotationBlocks = std::vector<Mat3, Eigen::aligned_allocator<Mat3>>;

/// d(pose perturbation)/d(dq) of apply_pose_increment from the same start, per free body: the
/// left Jacobian J_l(dq[3:6]) of its rotation (the identity for its translation): the force
/// Jacobian's perturbation is exp([dphi]x) R_WB at the incremented pose, not an added increment.
RotationBlocks pose_increment_jacobians(const Model& model, const Eigen::VectorXd& dq);

/// d(M(q) y)/d(pose perturbation) for a fixed y, per free body: J_W [y_w]x - [J_W y_w]x (the
/// inertia turns with the body; y_w the rotation part of the body's y).
RotationBlocks mass_pose_jacobians(const Model& model, const State& state,
                                   const Eigen::VectorXd& y);

/// A += scale B_i on the rotation rows and columns of each free body i, in place (A holds those
/// entries, as a Jacobian assembled from 6 x 6 body blocks does; else by a sparse sum).
void add_rotation_blocks(const Model& model, const RotationBlocks& B, double scale,
                         Eigen::SparseMatrix<double>& A);

/// A's rotation columns of each free body i times T_i, in place (A's columns of one body share
/// their rows, as in a Jacobian assembled from 6 x 6 body blocks; else by a sparse product).
void right_multiply_rotation_columns(const Model& model, const RotationBlocks& T,
                                     Eigen::SparseMatrix<double>& A);

/// A = B + A in A's storage, each entry summed as B_ij + A_ij (the bits of Eigen's sparse sum),
/// where every stored entry of B falls on A's pattern (A compressed); else false, A unchanged.
bool add_on_pattern(const Eigen::SparseMatrix<double>& B, Eigen::SparseMatrix<double>& A);

/// Per degree of freedom, the length that turns it into the largest displacement of a point
/// of its body: 1 for translations, the body's radius (farthest corner of its prism from the
/// centroid, m/rad) for rotations. A vector in m and rad weighted by it is in m: a small
/// segment's rotation counts by how far it moves the segment (docs/solvers.md, "Step control").
Eigen::VectorXd displacement_weights(const Model& model);

/// Velocities (v_W, w_W) of the free bodies as one vector, and back.
Eigen::VectorXd velocity_vector(const Model& model, const State& state);
void set_velocity(const Model& model, State& state, const Eigen::VectorXd& v);

/// Inertia of body i about its centroid in the world frame, R_WB J_B R_WB^T (kg m^2).
inline Mat3 inertia_W(const Model& model, const State& state, size_t i) {
  return state.R_WB[i] * model.bodies[i].J_B * state.R_WB[i].transpose();
}

/// Block-diagonal mass matrix diag(m I, R J_B R^T) of the free bodies.
Eigen::SparseMatrix<double> mass_matrix(const Model& model, const State& state);

/// M(q) x block by block, without forming M (x: one 6-vector per free body).
Eigen::VectorXd mass_times(const Model& model, const State& state, const Eigen::VectorXd& x);

/// Momentum vector (m v_W, J_W w_W) of the free bodies.
Eigen::VectorXd momentum(const Model& model, const State& state);

/// Kinetic energy of all bodies, J.
double kinetic_energy(const Model& model, const State& state);

/// Drive displacement at time t for the dynamic solvers: speed * t, capped at travel.
void set_drives_at_time(const Model& model, State& state, double t);

/// Throws DivergenceError naming the time, the most strained element and the quantity
/// when forces or the state are not finite or have blown up.
void check_finite(const Model& model, const State& state, const BodyForces& forces,
                  const char* where);

/// One-line description of the most strained element (for divergence messages).
std::string most_strained_element(const Model& model, const State& state);

}  // namespace finseg
