#include "fitting/fit_solve.hpp"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <memory>

#include "fitting/fit_model.hpp"

namespace finseg {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Scene values from the optimiser's variables u = x / scale (each near 1, so that a relative
// step and the trust region mean the same for every parameter).
std::vector<double> scene_values(const FitSpec& spec, const double* u) {
  std::vector<double> x;
  for (std::size_t i = 0; i < spec.parameters.size(); ++i)
    x.push_back(u[i] * spec.parameters[i].scale);
  return x;
}

// Residuals simulated - measured mean, every curve's points one after the other.
struct Residuals {
  const FitSpec* spec;
  const FitModel* model;
  const std::vector<MeasuredSpread>* measured;

  bool operator()(double const* const* u, double* r) const {
    std::vector<std::vector<double>> sim;
    try {
      sim = model->simulate(scene_values(*spec, u[0]));
    } catch (const std::exception&) {
      return false;  // a trial point the scene refuses or that diverges: the step is rejected
    }
    for (std::size_t k = 0, j = 0; k < sim.size(); ++k) {
      for (std::size_t i = 0; i < sim[k].size(); ++i) r[j++] = sim[k][i] - (*measured)[k].mean[i];
    }
    return true;
  }
};

class ProgressLines : public ceres::IterationCallback {
 public:
  ProgressLines(const FitProgress& progress, std::size_t m) : progress_(progress), m_(m) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (progress_) {
      progress_(fmt::format("iteration {}: rms {:.6g} N{}", s.iteration, std::sqrt(2 * s.cost / m_),
                            s.step_is_successful ? "" : " (step rejected)"));
    }
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const FitProgress& progress_;
  std::size_t m_;
};

double rms(const std::vector<std::vector<double>>& sim, const std::vector<MeasuredSpread>& meas,
           std::size_t m) {
  double sq = 0;
  for (std::size_t k = 0; k < sim.size(); ++k) {
    for (std::size_t i = 0; i < sim[k].size(); ++i) sq += std::pow(sim[k][i] - meas[k].mean[i], 2);
  }
  return std::sqrt(sq / m);
}

// Standard errors and correlations from the Jacobian J_u (in the scaled variables) at the
// solution: C_u = sigma^2 (J_u^T J_u)^-1, C_x = D C_u D with D = diag(scale).
void covariance(const FitSpec& spec, const Eigen::MatrixXd& J, FitResult& r) {
  const std::size_t n = spec.parameters.size();
  r.standard_errors.assign(n, kNaN);
  r.correlation = Eigen::MatrixXd::Constant(n, n, kNaN);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinV);
  const Eigen::VectorXd s = svd.singularValues();
  // Singular J^T J: some parameter (or combination) does not change the curves.
  if (s.size() == 0 || !(s(s.size() - 1) > 1e-10 * s(0))) return;
  const double sigma2 = r.rss / static_cast<double>(r.residuals - n);
  const Eigen::MatrixXd V = svd.matrixV();
  const Eigen::MatrixXd Cu = sigma2 * V * s.cwiseInverse().cwiseAbs2().asDiagonal() * V.transpose();
  for (std::size_t i = 0; i < n; ++i) {
    r.standard_errors[i] = spec.parameters[i].scale * std::sqrt(Cu(i, i));
    for (std::size_t j = 0; j < n; ++j)
      r.correlation(i, j) = Cu(i, j) / std::sqrt(Cu(i, i) * Cu(j, j));
  }
}

const char* termination_name(ceres::TerminationType t) {
  if (t == ceres::CONVERGENCE) return "convergence";
  if (t == ceres::NO_CONVERGENCE) return "no_convergence";
  return "failure";
}

}  // namespace

FitResult run_fit(const FitSpec& spec, const FitProgress& progress) {
  const FitModel model(spec);
  FitResult r;
  const std::size_t n = spec.parameters.size();
  for (const FitParameter& p : spec.parameters) r.initial.push_back(p.initial);
  for (const FitCurve& c : spec.curves) {
    r.measured.push_back(measured_spread(c.runs, c.x));
    r.residuals += c.x.size();
  }
  r.initial_curves = model.simulate(r.initial);  // errors here are the user's: thrown
  r.initial_rms = rms(r.initial_curves, r.measured, r.residuals);

  std::vector<double> u;
  for (const FitParameter& p : spec.parameters) u.push_back(p.initial / p.scale);
  ceres::NumericDiffOptions diff;
  diff.relative_step_size = spec.solver.relative_step;
  auto* cost = new ceres::DynamicNumericDiffCostFunction<Residuals, ceres::CENTRAL>(
      new Residuals{&spec, &model, &r.measured}, ceres::TAKE_OWNERSHIP, diff);
  cost->AddParameterBlock(static_cast<int>(n));
  cost->SetNumResiduals(static_cast<int>(r.residuals));
  ceres::Problem problem;
  problem.AddResidualBlock(cost, nullptr, u.data());
  for (std::size_t i = 0; i < n; ++i) {
    const FitParameter& p = spec.parameters[i];
    if (std::isfinite(p.lower)) problem.SetParameterLowerBound(u.data(), i, p.lower / p.scale);
    if (std::isfinite(p.upper)) problem.SetParameterUpperBound(u.data(), i, p.upper / p.scale);
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.logging_type = ceres::SILENT;
  options.max_num_iterations = spec.solver.max_iterations;
  options.function_tolerance = spec.solver.function_tolerance;
  options.parameter_tolerance = spec.solver.parameter_tolerance;
  options.gradient_tolerance = spec.solver.gradient_tolerance;
  ProgressLines lines(progress, r.residuals);
  options.callbacks.push_back(&lines);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  r.iterations = static_cast<int>(summary.iterations.size()) - 1;
  r.termination = termination_name(summary.termination_type);
  r.message = summary.message;
  r.values = scene_values(spec, u.data());
  for (std::size_t i = 0; i < n; ++i) {
    const FitParameter& p = spec.parameters[i];
    r.at_bound.push_back(r.values[i] <= p.lower || r.values[i] >= p.upper);
  }
  // The Jacobian at the solution (the simulation at the values and at +-h each).
  double cost_value = 0;
  ceres::CRSMatrix crs;
  std::vector<double> res;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(r.residuals, n);
  if (problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost_value, &res, nullptr, &crs)) {
    for (int row = 0; row < crs.num_rows; ++row) {
      for (int k = crs.rows[row]; k < crs.rows[row + 1]; ++k) J(row, crs.cols[k]) = crs.values[k];
    }
    r.rss = 2 * cost_value;
    covariance(spec, J, r);
  } else {
    r.rss = 2 * summary.final_cost;
    r.standard_errors.assign(n, kNaN);
    r.correlation = Eigen::MatrixXd::Constant(n, n, kNaN);
  }
  r.fitted_curves = model.simulate(r.values);
  r.final_rms = rms(r.fitted_curves, r.measured, r.residuals);
  r.simulations = model.simulations();
  return r;
}

}  // namespace finseg
