// Generalized-alpha on the Lie group of poses (Arnold & Bruls 2007, in the world-frame form of
// solvers/dofs): pose q_{n+1} = exp(h dq) q_n with dq = v_n + h (1/2 - beta) a_n + h beta
// a_{n+1}, v_{n+1} = v_n + h (1 - gamma) a_n + h gamma a_{n+1}, and the equations of motion
// M(q) vdot + gyro = g(q, v) holding exactly at t_{n+1}. Newton solves for vdot_{n+1}.
#include "solvers/generalized_alpha.hpp"

#include "solvers/dofs.hpp"
#include "solvers/implicit_newton.hpp"
#include "solvers/linear_solve.hpp"
#include "solvers/time_stepper.hpp"

namespace finseg {

AlphaParameters chung_hulbert(double rho_inf) {
  AlphaParameters p;
  p.alpha_m = (2 * rho_inf - 1) / (rho_inf + 1);
  p.alpha_f = rho_inf / (rho_inf + 1);
  p.gamma = 0.5 + p.alpha_f - p.alpha_m;
  p.beta = 0.25 * (p.gamma + 0.5) * (p.gamma + 0.5);
  return p;
}

namespace {

class GeneralizedAlpha final : public TimeStepper {
 public:
  GeneralizedAlpha(const SolverSettings& s, double tol)
      : p_(chung_hulbert(s.rho_inf)),
        max_iterations_(newton_iterations(s)),
        tol_(tol),
        newton_tol_(s.newton_tolerance * tol),
        at_points_(s.error_at_points) {
    reuse_.max_age = s.jacobian_reuse ? s.jacobian_max_age : 1;
    reuse_.krylov = s.krylov_steps;
  }

  // vdot_0 = M^-1 (g - gyro); the pseudo-acceleration starts equal to it.
  void begin(const Model& model, const State& state, const BodyForces& f) override {
    weights_ = at_points_ ? displacement_weights(model) : Eigen::VectorXd::Ones(model.num_dofs);
    const SolverMemory& m = state.solver;
    const auto n = static_cast<std::size_t>(model.num_dofs);
    if (m.t == state.t && m.vdot.size() == n && m.accel.size() == n) {
      vdot_ = Eigen::Map<const Eigen::VectorXd>(m.vdot.data(), model.num_dofs);
      a_ = Eigen::Map<const Eigen::VectorXd>(m.accel.data(), model.num_dofs);
      h_ = m.h_prev;
      return;
    }
    const Eigen::VectorXd rhs = generalized_forces(model, f) - gyroscopic_forces(model, state);
    if (!sparse_solve(mass_matrix(model, state), rhs, vdot_)) vdot_.setZero(model.num_dofs);
    a_ = vdot_;
    h_ = 0;
  }

  StepTry attempt(const Model& model, const State& start, double h, State& state, BodyForces& f,
                  SolverStats& stats) override {
    // a_n - vdot_n is O(h) (a lags vdot by (alpha_m - alpha_f) h): rescale it to the new step.
    const Eigen::VectorXd a = h_ > 0 ? Eigen::VectorXd(vdot_ + (h / h_) * (a_ - vdot_)) : a_;
    const Eigen::VectorXd v0 = velocity_vector(model, start);
    const double c = (1 - p_.alpha_f) / (1 - p_.alpha_m);
    const Eigen::VectorXd a_known = (p_.alpha_f * vdot_ - p_.alpha_m * a) / (1 - p_.alpha_m);
    AffineStep map;  // a_{n+1} = a_known + c vdot_{n+1}
    map.v0 = v0 + h * (1 - p_.gamma) * a + h * p_.gamma * a_known;
    map.cv = h * p_.gamma * c;
    map.dq0 = h * v0 + h * h * (0.5 - p_.beta) * a + h * h * p_.beta * a_known;
    map.cq = h * h * p_.beta * c;
    NewtonResidual res;
    res.b = Eigen::VectorXd::Zero(model.num_dofs);
    res.with_gyro = true;
    Eigen::VectorXd x = vdot_;
    StepTry r;
    r.converged = newton_solve(model, start, h, map, res, max_iterations_, newton_tol_, x, state, f,
                               stats, &reuse_, &weights_);
    if (!r.converged) return r;
    // Zienkiewicz & Xie (1991): local position error (beta - 1/6) h^2 (vdot_{n+1} - vdot_n).
    r.error = std::abs(p_.beta - 1.0 / 6.0) * h * h *
              weights_.cwiseProduct(x - vdot_).lpNorm<Eigen::Infinity>() / tol_;
    next_vdot_ = x;
    next_a_ = a_known + c * x;
    next_h_ = h;
    return r;
  }

  void accept(bool restart) override {
    if (restart) reuse_.stale = true;  // an event changed the forces' make-up
    vdot_ = next_vdot_;
    a_ = restart ? next_vdot_ : next_a_;
    h_ = next_h_;
  }

  void remember(SolverMemory& memory) const override {
    memory.vdot.assign(vdot_.data(), vdot_.data() + vdot_.size());
    memory.accel.assign(a_.data(), a_.data() + a_.size());
    memory.h_prev = h_;
  }

  void forget_newton_matrix() override { reuse_.reset(); }
  double error_order() const override { return 3; }

 private:
  AlphaParameters p_;
  int max_iterations_;
  double tol_;
  double newton_tol_;        // m and rad (or m: error_at_points)
  NewtonReuse reuse_;        // the iteration matrix kept between steps
  bool at_points_;           // SolverSettings::error_at_points
  Eigen::VectorXd weights_;  // per DOF, what the error's norm multiplies it by
  Eigen::VectorXd vdot_, a_, next_vdot_, next_a_;
  double h_ = 0, next_h_ = 0;
};

}  // namespace

std::unique_ptr<TimeStepper> make_generalized_alpha(const SolverSettings& settings, double tol) {
  return std::make_unique<GeneralizedAlpha>(settings, tol);
}

}  // namespace finseg
