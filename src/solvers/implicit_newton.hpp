// Newton plumbing shared by the implicit schemes (backward Euler, generalized-alpha): each
// step solves for one vector x of num_dofs unknowns on which the end-of-step pose increment
// and velocity depend affinely, with the exact sparse Jacobian of the forces.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solvers/solver.hpp"
#include "solvers/volume_stiffness.hpp"

namespace finseg {

/// End-of-step pose and velocity as affine functions of the unknown x:
/// pose increment dq = dq0 + cq x (applied to the start state), velocity v = v0 + cv x.
struct AffineStep {
  Eigen::VectorXd dq0, v0;
  double cq = 0, cv = 0;
};

/// Residual r(x) = M(q) x - b - s (g(q, v) - gyro(q, v)), gyro = (0, w_W x J_W w_W) when
/// `with_gyro` (acceleration form) and 0 otherwise (momentum form).
struct NewtonResidual {
  Eigen::VectorXd b;
  double s = 1;
  bool with_gyro = false;
};

/// The iteration matrix kept across Newton iterations and steps (modified Newton,
/// docs/solvers.md): its factorization, what it was made with, and how well it contracts.
/// Owned by the time stepper; `max_age` 1 is full Newton (a new matrix every iteration).
struct NewtonReuse {
  int max_age = 1;  ///< Newton iterations one factorization serves at most
  /// Where the kept matrix stops contracting, try GMRES on the new matrix preconditioned by
  /// its factor before factoring the new one (docs/solvers.md, "Krylov steps on a kept factor").
  bool krylov = true;
  KeptNewtonMatrix matrix;
  double s_cq = 0, s_cv = 0;  ///< the coefficients of dF/dq and dF/dv it was made with
  bool symmetric = false;     ///< made for the symmetric (Cholesky) path
  /// A nonsymmetric matrix up to this asymmetry ratio ||A - A^T||_F / ||A||_F is kept as the
  /// factor of its symmetric part (docs/solvers.md, "Modified Newton"); 0: none.
  double approximate_asymmetry = 1e-3;
  bool approximate = false;  ///< the kept factor is of the symmetric part of a nonsymmetric matrix
  int age = 0;               ///< iterations it has served
  double eta = 1;            ///< theta / (1 - theta) of its last measured contraction rate theta
  /// An event changed the forces' make-up (a contact point made or lost, a crease snapped):
  /// the next iteration makes a new matrix, which the kept factor may still precondition.
  bool stale = false;
  /// Forgets the matrix and its history (a run resumed from here starts the same way).
  void reset() {
    matrix.clear();
    stale = false;
    age = 0;
    eta = 1;
  }
};

/// Places `state` at `start` advanced by `h` in time with pose increment dq and velocity v.
void place_state(const Model& model, const State& start, double h, const Eigen::VectorXd& dq,
                 const Eigen::VectorXd& v, State& state);

/// Newton iterations on r(x) = 0 from the guess in `x`, stopping when the pose correction
/// |cq W dx|_inf falls below `pose_tol` (W: `weights` per DOF, else 1); a correction that does not
/// lower |r| is halved (up to 5 times). With `reuse` (max_age > 1) the iteration matrix is kept
/// while it contracts (docs/solvers.md, "Modified Newton"); the residual is always exact. On
/// success leaves `state` at the solution with its forces in `f` and returns true; false when
/// Newton fails (not finite, singular, or max_iterations reached).
bool newton_solve(const Model& model, const State& start, double h, const AffineStep& map,
                  const NewtonResidual& res, int max_iterations, double pose_tol,
                  Eigen::VectorXd& x, State& state, BodyForces& f, SolverStats& stats,
                  NewtonReuse* reuse = nullptr, const Eigen::VectorXd* weights = nullptr);

/// The residual r(x) of newton_solve and its iteration matrix dr/dx at x, `state` placed there
/// (what each Newton iteration with a new matrix solves with until a solve takes friction's
/// secant, docs/solvers.md; for tests and diagnostics).
void newton_linearisation(const Model& model, const State& start, double h, const AffineStep& map,
                          const NewtonResidual& res, const Eigen::VectorXd& x, State& state,
                          Eigen::VectorXd& r, Eigen::SparseMatrix<double>& A);

/// One backward-Euler step of h from `start` (src/solvers/implicit_euler.cpp): solves
/// M(q1) v1 - p0 = h g(q0 + h v1, v1) for v1 by newton_solve from the guess in `v`.
bool backward_euler_solve(const Model& model, const State& start, double h, int max_iterations,
                          double pose_tol, Eigen::VectorXd& v, State& state, BodyForces& f,
                          SolverStats& stats, NewtonReuse* reuse,
                          const Eigen::VectorXd* weights = nullptr);

/// Gyroscopic vector (0, w_W x J_W w_W) of the free bodies.
Eigen::VectorXd gyroscopic_forces(const Model& model, const State& state);

}  // namespace finseg
