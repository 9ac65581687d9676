// Sums every force on every body: force elements (bushings, creases), loads, gravity,
// drives and contact. Optionally also the exact Jacobian of the generalized forces.
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "elements/block_matrix.hpp"
#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// Resultant on each body (about its centroid, world frame) plus the potential energy.
struct BodyForces {
  std::vector<Vec3> f_W;
  std::vector<Vec3> tau_W;
  double potential_energy = 0;  ///< elastic + gravity + gauge springs + contact, J
};

/// d(generalized force)/d(pose perturbation) and d(...)/d(velocity), both num_dofs square.
/// Pose perturbation of a free body: p_W += dp, R_WB = exp([dphi]x) R_WB (world frame).
struct ForceJacobian {
  Eigen::SparseMatrix<double> dq;
  Eigen::SparseMatrix<double> dv;
  /// false: only dq is wanted (static solver); dv is left empty and the automatic
  /// differentiation carries half the derivatives.
  bool with_velocity = true;
  /// true: force elements differentiated automatically (the closed forms' test oracle,
  /// about 30 times slower) instead of by their closed-form Jacobians.
  bool autodiff = false;
  /// true: Newton's iteration matrix wanted, in which continuous friction takes its secant
  /// mu(v)/v along the slip, not its tangent (docs/solvers.md, "Friction's secant").
  bool friction_secant = false;
  /// Set by the evaluation: some friction point's secant differed from its tangent, so the
  /// matrices are not the exact Jacobian.
  bool secant_differs = false;
  /// Assembly scratch, kept between evaluations so that its storage is reused.
  BlockMatrix dq_blocks, dv_blocks;
};

/// Evaluates all forces at `state`; fills `jac` too when it is not null.
void compute_forces(const Model& model, const State& state, BodyForces& out,
                    ForceJacobian* jac = nullptr);

/// True when every position-dependent force of `model` derives from a potential while the
/// history (crease openings) is held: force elements, crease laws, plate cells, gravity, dead
/// point forces, drive gauges. Its stiffness -dq is then symmetric but for the
/// left-trivialisation term: body i's rotation block has the skew part (1/2)[tau_i]x (tau_i
/// the torque on it), which vanishes at equilibrium. Follower loads, dead moments, pressure,
/// gas chambers and contact (friction) make it false (docs/solvers.md, "Linear solves").
bool conservative_stiffness(const Model& model);

/// True when some force depends on the velocities (element, drive or contact damping,
/// friction): their Jacobians are not symmetric away from rest.
bool has_velocity_forces(const Model& model);

/// Generalized force vector (num_dofs) of the free bodies, from per-body resultants.
Eigen::VectorXd generalized_forces(const Model& model, const BodyForces& forces);

/// Updates history variables (crease angle and opening count, contact anchors) after an
/// accepted step or a converged equilibrium; `start`: the state a run starts from.
void commit_history(const Model& model, State& state, bool start = false);

}  // namespace finseg
