#include "solvers/implicit_newton.hpp"

#include <cmath>
#include <utility>

#include "core/so3.hpp"
#include "solvers/dofs.hpp"
#include "solvers/krylov_step.hpp"
#include "solvers/linear_solve.hpp"
#include "solvers/volume_stiffness.hpp"

namespace finseg {
namespace {

// d(w x J_W w)/dw = [w]x J_W - [J_W w]x per free body.
RotationBlocks gyroscopic_jacobians(const Model& model, const State& state) {
  RotationBlocks G(model.bodies.size(), Mat3::Zero());
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    if (model.dof_of_body[i] < 0) continue;
    const Mat3 J_W = inertia_W(model, state, i);
    const Vec3& w = state.w_W[i];
    G[i] = hat<double>(w) * J_W - hat<double>(J_W * w);
  }
  return G;
}

// d(w x J_W w)/d(pose perturbation) = [w]x d(J_W w)/d(pose): the inertia turns with the body.
RotationBlocks gyroscopic_pose_jacobians(const Model& model, const State& state) {
  RotationBlocks G = mass_pose_jacobians(model, state, velocity_vector(model, state));
  for (size_t i = 0; i < model.bodies.size(); ++i) G[i] = hat<double>(state.w_W[i]) * G[i];
  return G;
}

}  // namespace

Eigen::VectorXd gyroscopic_forces(const Model& model, const State& state) {
  Eigen::VectorXd g = Eigen::VectorXd::Zero(model.num_dofs);
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    const Mat3 J_W = inertia_W(model, state, i);
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

namespace {

// The Jacobian's scratch, kept on the thread across solves: its storage and its block layout
// (elements/block_matrix.hpp) then serve every step's evaluations, not only one solve's.
ForceJacobian& scratch_jacobian() {
  thread_local ForceJacobian jac;
  return jac;
}

// The residual of one Newton solve, and on request its iteration matrix, at a point x.
class Linearisation {
 public:
  Linearisation(const Model& model, const State& start, double h, const AffineStep& map,
                const NewtonResidual& res, State& state, BodyForces& f, SolverStats& stats)
      : model_(model),
        start_(start),
        h_(h),
        map_(map),
        res_(res),
        state_(state),
        f_(f),
        stats_(stats) {
    jac_.friction_secant = false;
    jac_.secant_differs = false;  // the scratch may hold the last solve's
  }

  // Places the state at x_at and evaluates r there (forces in f), and the matrix A when
  // `with_matrix` (the force Jacobian).
  void at(const Eigen::VectorXd& x_at, bool with_matrix) {
    place(x_at);
    compute_forces(model_, state_, f_, with_matrix ? &jac_ : nullptr);
    ++stats_.force_evaluations;
    if (with_matrix) ++stats_.jacobian_evaluations;
    Eigen::VectorXd g = generalized_forces(model_, f_);
    if (res_.with_gyro) g -= gyroscopic_forces(model_, state_);
    r = mass_times(model_, state_, x_at) - res_.b - res_.s * g;
    if (!with_matrix) return;
    // dr/dx = M - s cv (dg/dv - dgyro/dv) + cq (d(M x)/dq - s (dg/dq - dgyro/dq)) J_l: the pose
    // is exp([dq]x) R_start, the Jacobians' perturbation exp([dphi]x) R, hence the chain rule
    // through the exponential map, J_l (docs/solvers.md, "The iteration matrix").
    // Worked on in place: jac_ is this evaluation's scratch, refilled at the next.
    Eigen::SparseMatrix<double>& dv = jac_.dv;
    Eigen::SparseMatrix<double>& pose = jac_.dq;
    pose *= -res_.s;
    add_rotation_blocks(model_, mass_pose_jacobians(model_, state_, x_at), 1, pose);
    if (res_.with_gyro) {
      add_rotation_blocks(model_, gyroscopic_jacobians(model_, state_), -1, dv);
      add_rotation_blocks(model_, gyroscopic_pose_jacobians(model_, state_), res_.s, pose);
    }
    right_multiply_rotation_columns(
        model_, pose_increment_jacobians(model_, map_.dq0 + map_.cq * x_at), pose);
    // The sum in pose's storage where M's and dv's entries fall on its pattern (the Jacobian's
    // diagonal blocks hold them): no new matrix of the Jacobian's size (30 ms at 10^4
    // segments), the same values.
    Eigen::SparseMatrix<double> M_dv = mass_matrix(model_, state_) - (res_.s * map_.cv) * dv;
    pose *= map_.cq;
    if (add_on_pattern(M_dv, pose)) {
      A.swap(pose);  // the scratch takes A's old storage, to be refilled
    } else {
      A = M_dv + pose;
    }
  }

  // A is dr/dx; false where friction took its secant (docs/solvers.md, "Friction's secant"):
  // then Newton's test alone does not bound the error left. (Only an evaluation with the
  // matrix sets the flag.)
  bool exact() const { return !jac_.secant_differs; }

  // From here on the matrices take friction's secant (docs/solvers.md, "Friction's secant").
  void take_friction_secant() {
    const ContactDef& c = model_.contact;
    if (!c.enabled || c.friction == FrictionModel::None || jac_.friction_secant) return;
    ++stats_.secant_solves;
    jac_.friction_secant = true;
  }

  // The converged end state at x, with its forces.
  void finish(const Eigen::VectorXd& x) {
    place(x);
    compute_forces(model_, state_, f_);
    ++stats_.force_evaluations;
  }

  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> A;

 private:
  void place(const Eigen::VectorXd& x) {
    place_state(model_, start_, h_, map_.dq0 + map_.cq * x, map_.v0 + map_.cv * x, state_);
  }
  const Model& model_;
  const State& start_;
  double h_;
  const AffineStep& map_;
  const NewtonResidual& res_;
  State& state_;
  BodyForces& f_;
  SolverStats& stats_;
  ForceJacobian& jac_ = scratch_jacobian();
};

// Backtracking on |r|: a full step that does not lower the residual is halved (at most
// kHalvings times; the shortest is taken then). Without it Newton cycles for ever between the
// two sides of a steep, saturating force such as regularised Coulomb friction, whose plateau's
// tangent jumps the slip velocity across zero and back (docs/solvers.md). Where no halving
// lowers it (many points thrown across their stick bands at once), the solve's matrices take
// friction's secant from there on. Moves x, evaluates the full step with the matrix when
// `matrix_full`, and the point a halving ends at with it (once that point is known: the tries
// on the way need only their residual); returns the number of halvings.
int backtrack(Linearisation& lin, const Eigen::VectorXd& dx, bool matrix_full, Eigen::VectorXd& x) {
  const double merit = lin.r.squaredNorm();
  constexpr int kHalvings = 5;
  double a = 1;
  Eigen::VectorXd x_try;
  int k = 0;
  bool lowered = false;
  for (;; ++k) {
    x_try = x + a * dx;
    lin.at(x_try, k == 0 && matrix_full);
    lowered = lin.r.allFinite() && lin.r.squaredNorm() < merit;
    if (k == kHalvings || lowered) break;
    a *= 0.5;
  }
  x = x_try;
  if (!lowered) lin.take_friction_secant();
  if (k > 0) lin.at(x, true);
  return k;
}

// A kept matrix serves while each of its steps lowers |r|_2 at least by this factor. On the
// lab cone pulls at newton_tolerance 0.1 (BENCHMARKS.md, "Steps spread to the outputs") 0.8
// against 0.5: 175 segments the same CPU, 700 segments 27 % fewer factorizations and 23 % less
// CPU; where the symmetric part serves, fewer new ones also fail to contract and need LU.
constexpr double kTheta = 0.8;
// ... and while s cq and s cv (the step size) stay within this ratio of those it was made
// with: for backward Euler h within 1.22 of it.
constexpr double kCoefficientRatio = 1.5;

// The error left after a step |dx| on a matrix that contracts at rate theta is at most
// eta |dx|, eta = theta / (1 - theta) (Hairer & Wanner IV.8); theta >= 1, no bound.
double error_factor(double theta) {
  return theta < 1 ? theta / (1 - theta) : INFINITY;
}

bool near(double a, double b) {
  return a == b || (a * b > 0 && std::abs(std::log(a / b)) <= std::log(kCoefficientRatio));
}

// Makes `lin.A` (at the iterate, with coefficients s_cq and s_cv) the kept matrix and solves
// with it for the step dx: as the factor of its symmetric part where the model is symmetric, or
// nearly so and LU is not required (`exact_only`), else as LU with the gas terms `gas`.
bool factor_new_matrix(const Linearisation& lin, VolumeStiffness gas, double s_cq, double s_cv,
                       bool symmetric, bool exact_only, NewtonReuse& k, Eigen::VectorXd& dx) {
  k.age = 0;
  k.s_cq = s_cq;
  k.s_cv = s_cv;
  k.symmetric = symmetric;
  const bool nearly = !symmetric && gas.empty();  // may stand for its symmetric part
  const Eigen::SparseMatrix<double> At =
      nearly ? Eigen::SparseMatrix<double>(lin.A.transpose()) : Eigen::SparseMatrix<double>();
  const double asymmetry = nearly ? asymmetry_ratio(lin.A, At) : 0;
  k.approximate = !exact_only && asymmetry > 0 && asymmetry <= k.approximate_asymmetry;
  if (symmetric) {
    return k.matrix.factor_and_solve(SymmetricMatrix::symmetric_part_of(lin.A), -lin.r, dx);
  }
  if (k.approximate) {
    return k.matrix.factor_and_solve(SymmetricMatrix::symmetric_part_of(lin.A, At), -lin.r, dx);
  }
  return k.matrix.factor_and_solve(lin.A, s_cq, std::move(gas), -lin.r, dx);
}

// GMRES on a new matrix preconditioned by the kept factor: converged within this, its step
// counts as the new matrix's (docs/solvers.md, "Krylov steps on a kept factor").
constexpr KrylovSettings kKrylov{};

// True when the kept factor may precondition the matrix at coefficients s_cq, s_cv: one it
// would still serve but for its contraction, of a model without gas terms (which A leaves out).
bool may_precondition(const NewtonReuse& k, const VolumeStiffness& gas, double s_cq, double s_cv,
                      bool symmetric) {
  return k.krylov && gas.empty() && k.matrix.valid() && k.symmetric == symmetric &&
         k.age < k.max_age && near(s_cq, k.s_cq) && near(s_cv, k.s_cv);
}

// Newton with the iteration matrix kept while it contracts (docs/solvers.md, "Modified
// Newton"); the residual is always exact, so the solution is Newton's to the tolerance.
// A kept matrix is an approximation anyway, so a nearly symmetric one (damping, friction and
// the rotation Jacobian's skew part: 2e-6 on the 6 300-segment lab cone in contact) is kept
// as the Cholesky factor of its symmetric part, 3x cheaper than its LU there; its steps are
// tested as a kept matrix's, and where one stops contracting the solve goes on with LU.
bool modified_newton(const Model& model, const State& state, const AffineStep& map,
                     const NewtonResidual& res, int max_iterations, double pose_tol,
                     const Eigen::VectorXd& weights, bool symmetric, Linearisation& lin,
                     Eigen::VectorXd& x, SolverStats& stats, NewtonReuse& k) {
  const double s_cq = res.s * map.cq, s_cv = res.s * map.cv;
  bool renew = k.stale || !k.matrix.valid() || k.symmetric != symmetric || k.age >= k.max_age ||
               !near(s_cq, k.s_cq) || !near(s_cv, k.s_cv);
  k.stale = false;
  lin.at(x, renew);
  double dx_prev = 0;       // |cq dx| of the last iteration on the same matrix in this solve
  bool exact_only = false;  // a symmetric part stopped contracting in this solve: LU from here
  for (int it = 1; it <= max_iterations; ++it) {
    ++stats.newton_iterations;
    if (!lin.r.allFinite()) return false;
    Eigen::VectorXd dx;
    const bool fresh = renew;
    bool krylov = false;  // this fresh step solved by GMRES on the kept factor
    if (fresh) {
      dx_prev = 0;
      VolumeStiffness gas = volume_stiffness(model, state);
      if (may_precondition(k, gas, s_cq, s_cv, symmetric)) {
        int its = 0;
        krylov = krylov_solve(lin.A, k.matrix, -lin.r, kKrylov, dx, &its);
        stats.krylov_iterations += its;
      }
      if (krylov) {
        ++stats.krylov_steps;
      } else {
        ++stats.factorizations;
        if (!factor_new_matrix(lin, std::move(gas), s_cq, s_cv, symmetric, exact_only, k, dx)) {
          return false;
        }
      }
    } else if (!k.matrix.solve(-lin.r, dx)) {
      lin.at(x, true);  // (cannot happen with a factor that solved once; renewed all the same)
      renew = true;
      continue;
    }
    ++k.age;
    const double step = map.cq * weights.cwiseProduct(dx).lpNorm<Eigen::Infinity>();
    // Contraction rate theta = |dx_k| / |dx_k-1| on one matrix.
    if (!fresh && dx_prev > 0) k.eta = error_factor(step / dx_prev);
    // Fresh and exact, Newton's test; else also the error left after the step.
    const bool exact = fresh && lin.exact() && (krylov || !k.approximate);
    if (step < pose_tol && (exact || k.eta * step < pose_tol)) {
      x += dx;
      lin.finish(x);
      return true;
    }
    dx_prev = step;
    if (fresh) {
      // A step that needed halving leaves the region where this matrix is good (or, made of
      // a symmetric part, shows that part to be poor).
      renew = backtrack(lin, dx, false, x) > 0;
      exact_only = exact_only || (renew && k.approximate && !krylov);
      continue;
    }
    const double merit = lin.r.squaredNorm();
    const Eigen::VectorXd x_try = x + dx;
    const bool old = k.age >= k.max_age;
    lin.at(x_try, old);
    const double ratio = lin.r.allFinite() ? std::sqrt(lin.r.squaredNorm() / merit) : INFINITY;
    // (Its first kept step, at the point where it was made: an exact matrix contracts there
    // quadratically, so a slow one is the symmetric part's fault; later ones may be staleness.)
    exact_only = exact_only || (k.approximate && k.age == 2 && ratio > kTheta);
    if (ratio >= 1) {  // a kept matrix whose step does not lower |r| is renewed where it failed
      lin.at(x, true);
      renew = true;
      continue;
    }
    x = x_try;
    renew = old || ratio > kTheta;
    if (renew && !old) lin.at(x, true);  // contracting too slowly: a new matrix here
  }
  return false;
}

}  // namespace

void newton_linearisation(const Model& model, const State& start, double h, const AffineStep& map,
                          const NewtonResidual& res, const Eigen::VectorXd& x, State& state,
                          Eigen::VectorXd& r, Eigen::SparseMatrix<double>& A) {
  BodyForces f;
  SolverStats stats;
  Linearisation lin(model, start, h, map, res, state, f, stats);
  lin.at(x, true);
  r = lin.r;
  A = lin.A;
}

bool newton_solve(const Model& model, const State& start, double h, const AffineStep& map,
                  const NewtonResidual& res, int max_iterations, double pose_tol,
                  Eigen::VectorXd& x, State& state, BodyForces& f, SolverStats& stats,
                  NewtonReuse* reuse, const Eigen::VectorXd* weights) {
  // A conservative, undamped model's iteration matrix is symmetric but for the skew part of
  // its rotation Jacobian ((1/2)[tau]x per body, elements/assemble.hpp) and of the gyroscopic
  // term, both small per step like the derivatives of M(q) left out already: its symmetric
  // part goes to the sparse Cholesky instead of LU (docs/solvers.md, "Linear solves").
  const bool symmetric = conservative_stiffness(model) && !has_velocity_forces(model);
  Linearisation lin(model, start, h, map, res, state, f, stats);
  const Eigen::VectorXd W =
      weights != nullptr ? *weights : Eigen::VectorXd(Eigen::VectorXd::Ones(model.num_dofs));
  if (reuse != nullptr && reuse->max_age > 1) {
    return modified_newton(model, state, map, res, max_iterations, pose_tol, W, symmetric, lin, x,
                           stats, *reuse);
  }
  lin.at(x, true);
  double step_prev = 0;  // the last iteration's |cq dx|
  for (int it = 1; it <= max_iterations; ++it) {
    ++stats.newton_iterations;
    if (!lin.r.allFinite()) return false;
    Eigen::VectorXd dx;
    ++stats.factorizations;
    const bool solved =
        symmetric ? sparse_solve(SymmetricMatrix::symmetric_part_of(lin.A), -lin.r, dx)
                  : solve_with_volume_stiffness(lin.A, res.s * map.cq,
                                                volume_stiffness(model, state), -lin.r, dx);
    if (!solved) return false;
    const double step = map.cq * W.cwiseProduct(dx).lpNorm<Eigen::Infinity>();
    // A secant's steps contract linearly: the error left is bounded by eta |dx| as above.
    const bool bounded =
        lin.exact() || (step_prev > 0 && error_factor(step / step_prev) * step < pose_tol);
    if (step < pose_tol && bounded) {
      x += dx;
      lin.finish(x);
      return true;
    }
    step_prev = step;
    backtrack(lin, dx, true, x);
  }
  return false;
}

}  // namespace finseg
