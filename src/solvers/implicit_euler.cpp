// Implicit backward Euler on (pose, momentum) with Newton on the exact sparse Jacobian and
// the local error estimate h/2 |v_{n+1} - v_n| (the role of Adams' GSTIFF). Backward Euler
// dissipates: it never adds energy to an undriven system.
#include "solvers/dofs.hpp"
#include "solvers/implicit_newton.hpp"
#include "solvers/time_stepper.hpp"

namespace finseg {

bool backward_euler_solve(const Model& model, const State& start, double h, int max_iterations,
                          double pose_tol, Eigen::VectorXd& v, State& state, BodyForces& f,
                          SolverStats& stats, NewtonReuse* reuse, const Eigen::VectorXd* weights) {
  AffineStep map;
  map.dq0 = Eigen::VectorXd::Zero(model.num_dofs);
  map.v0 = Eigen::VectorXd::Zero(model.num_dofs);
  map.cq = h;
  map.cv = 1;
  NewtonResidual res;
  res.b = momentum(model, start);
  res.s = h;
  return newton_solve(model, start, h, map, res, max_iterations, pose_tol, v, state, f, stats,
                      reuse, weights);
}

namespace {

class BackwardEuler final : public TimeStepper {
 public:
  BackwardEuler(const SolverSettings& s, double tol)
      : max_iterations_(newton_iterations(s)),
        tol_(tol),
        newton_tol_(s.newton_tolerance * tol),
        at_points_(s.error_at_points) {
    reuse_.max_age = s.jacobian_reuse ? s.jacobian_max_age : 1;
    reuse_.krylov = s.krylov_steps;
  }

  void begin(const Model& model, const State&, const BodyForces&) override {
    last_ = {};
    weights_ = at_points_ ? displacement_weights(model) : Eigen::VectorXd::Ones(model.num_dofs);
  }

  StepTry attempt(const Model& model, const State& start, double h, State& state, BodyForces& f,
                  SolverStats& stats) override {
    const Eigen::VectorXd v0 = velocity_vector(model, start);
    Eigen::VectorXd v = predicted_velocity(v0, h);
    tried_ = {v0, h};
    StepTry r;
    r.converged = backward_euler_solve(model, start, h, max_iterations_, newton_tol_, v, state, f,
                                       stats, &reuse_, &weights_);
    if (r.converged) {
      r.error = 0.5 * h * weights_.cwiseProduct(v - v0).lpNorm<Eigen::Infinity>() / tol_;
    }
    return r;
  }

  void remember(SolverMemory&) const override {}  // none at outputs, where it is dropped
  // An event changed the forces' make-up: the next step starts with a new matrix, and from
  // its start velocity (the last step's change belongs to forces that no longer act).
  void accept(bool restart) override {
    if (restart) reuse_.stale = true;
    last_ = restart ? LastStep{} : tried_;
  }
  // At outputs, so that a run resumed there starts its Newton iterations the same way.
  void forget_newton_matrix() override {
    reuse_.reset();
    last_ = {};
  }
  double error_order() const override { return 2; }

 private:
  int max_iterations_;
  double tol_;
  double newton_tol_;        // m and rad (or m: error_at_points)
  NewtonReuse reuse_;        // the iteration matrix kept between steps
  bool at_points_;           // SolverSettings::error_at_points
  Eigen::VectorXd weights_;  // per DOF, what the error's norm multiplies it by

  // A step's start velocity and length (h = 0: none).
  struct LastStep {
    Eigen::VectorXd v0;
    double h = 0;
  };
  // Newton's first iterate: the velocity the last accepted step's change, continued over h,
  // reaches (constant acceleration), else v0. On the lab cone pulls it needs 18 % fewer Newton
  // iterations than v0 (docs/solvers.md); the solution is Newton's to its tolerance either way.
  Eigen::VectorXd predicted_velocity(const Eigen::VectorXd& v0, double h) const {
    if (!(last_.h > 0) || last_.v0.size() != v0.size()) return v0;
    return v0 + (h / last_.h) * (v0 - last_.v0);
  }
  LastStep last_, tried_;  // the last accepted step; the last one tried
};

}  // namespace

std::unique_ptr<TimeStepper> make_backward_euler(const SolverSettings& settings, double tol) {
  return std::make_unique<BackwardEuler>(settings, tol);
}

}  // namespace finseg
