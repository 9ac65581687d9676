#include "solvers/implicit_newton.hpp"

#include <vector>

#include "core/so3.hpp"
#include "solvers/dofs.hpp"
#include "solvers/linear_solve.hpp"
#include "solvers/volume_stiffness.hpp"

namespace finseg {
namespace {

// d(w x J_W w)/dw = [w]x J_W - [J_W w]x per free body (rotation block only).
Eigen::SparseMatrix<double> gyroscopic_jacobian(const Model& model, const State& state) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(9 * model.bodies.size());
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    const Mat3 J_W = state.R_WB[i] * model.bodies[i].J_B * state.R_WB[i].transpose();
    const Vec3& w = state.w_W[i];
    const Mat3 G = hat<double>(w) * J_W - hat<double>(J_W * w);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) t.emplace_back(d + 3 + r, d + 3 + c, G(r, c));
    }
  }
  Eigen::SparseMatrix<double> G(model.num_dofs, model.num_dofs);
  G.setFromTriplets(t.begin(), t.end());
  return G;
}

}  // namespace

Eigen::VectorXd gyroscopic_forces(const Model& model, const State& state) {
  Eigen::VectorXd g = Eigen::VectorXd::Zero(model.num_dofs);
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    const Mat3 J_W = state.R_WB[i] * model.bodies[i].J_B * state.R_WB[i].transpose();
    g.segment<3>(d + 3) = state.w_W[i].cross(J_W * state.w_W[i]);
  }
  return g;
}

void place_state(const Model& model, const State& start, double h, const Eigen::VectorXd& dq,
                 const Eigen::VectorXd& v, State& state) {
  state = start;
  state.t = start.t + h;
  set_drives_at_time(model, state, state.t);
  apply_pose_increment(model, state, dq);
  set_velocity(model, state, v);
}

bool newton_solve(const Model& model, const State& start, double h, const AffineStep& map,
                  const NewtonResidual& res, int max_iterations, double pose_tol,
                  Eigen::VectorXd& x, State& state, BodyForces& f, SolverStats& stats) {
  ForceJacobian jac;
  // A conservative, undamped model's iteration matrix is symmetric but for the skew part of
  // its rotation Jacobian ((1/2)[tau]x per body, elements/assemble.hpp) and of the gyroscopic
  // term, both small per step like the derivatives of M(q) left out already: its symmetric
  // part goes to the sparse Cholesky instead of LU (docs/solvers.md, "Linear solves").
  const bool symmetric = conservative_stiffness(model) && !has_velocity_forces(model);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> A;
  // Residual and iteration matrix at x_at (forces and Jacobian evaluated there).
  const auto linearise = [&](const Eigen::VectorXd& x_at) {
    place_state(model, start, h, map.dq0 + map.cq * x_at, map.v0 + map.cv * x_at, state);
    compute_forces(model, state, f, &jac);
    ++stats.force_evaluations;
    ++stats.jacobian_evaluations;
    const Eigen::SparseMatrix<double> M = mass_matrix(model, state);
    Eigen::VectorXd g = generalized_forces(model, f);
    Eigen::SparseMatrix<double> dv = jac.dv;
    if (res.with_gyro) {
      g -= gyroscopic_forces(model, state);
      dv -= gyroscopic_jacobian(model, state);
    }
    r = M * x_at - res.b - res.s * g;
    A = M - (res.s * map.cv) * dv - (res.s * map.cq) * jac.dq;
  };
  linearise(x);
  for (int it = 1; it <= max_iterations; ++it) {
    ++stats.newton_iterations;
    if (!r.allFinite()) return false;
    Eigen::VectorXd dx;
    const bool solved = symmetric ? sparse_solve(SymmetricMatrix::symmetric_part_of(A), -r, dx)
                                  : solve_with_volume_stiffness(
                                        A, res.s * map.cq, volume_stiffness(model, state), -r, dx);
    if (!solved) return false;
    if (map.cq * dx.lpNorm<Eigen::Infinity>() < pose_tol) {
      x += dx;
      place_state(model, start, h, map.dq0 + map.cq * x, map.v0 + map.cv * x, state);
      compute_forces(model, state, f);
      ++stats.force_evaluations;
      return true;
    }
    // Backtracking on |r|: a full step that does not lower the residual is halved (at most
    // kHalvings times; the shortest is taken then). Without it Newton cycles for ever between
    // the two sides of a steep, saturating force such as regularised Coulomb friction, whose
    // plateau's tangent jumps the slip velocity across zero and back (docs/solvers.md).
    const double merit = r.squaredNorm();
    constexpr int kHalvings = 5;
    double a = 1;
    Eigen::VectorXd x_try;
    for (int k = 0;; ++k) {
      x_try = x + a * dx;
      linearise(x_try);
      if (k == kHalvings || (r.allFinite() && r.squaredNorm() < merit)) break;
      a *= 0.5;
    }
    x = x_try;
  }
  return false;
}

}  // namespace finseg
