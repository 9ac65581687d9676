// Helpers shared by the solvers: moving between State and DOF vectors, mass matrices,
// energies and the divergence diagnosis.
#pragma once

#include <Eigen/SparseCore>
#include <string>

#include "elements/assemble.hpp"
#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// Applies a pose increment: p_W += dq[0:3], R_WB = exp([dq[3:6]]x) R_WB per free body.
void apply_pose_increment(const Model& model, State& state, const Eigen::VectorXd& dq);

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
