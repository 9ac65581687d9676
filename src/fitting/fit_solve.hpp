// Nonlinear least squares with bounds (Ceres' Levenberg-Marquardt, central-difference
// derivatives): the fitted values, their standard errors and correlations from the Jacobian
// at the solution, and the simulated curves before and after (docs/fit.md).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "comparison/compare.hpp"
#include "fitting/fit_spec.hpp"

namespace finseg {

/// What a fit found. Standard errors: sigma^2 (J^T J)^-1 with sigma^2 = RSS / (m - n) (m
/// residuals, n parameters); NaN when J^T J is singular (a parameter the curves do not fix).
struct FitResult {
  std::vector<double> initial, values, standard_errors;  ///< scene units
  std::vector<bool> at_bound;                            ///< value on its lower or upper bound
  Eigen::MatrixXd correlation;                           ///< n x n, NaN where not defined
  int iterations = 0;         ///< Levenberg-Marquardt iterations (successful and not)
  long simulations = 0;       ///< simulations run, derivatives and standard errors included
  std::string termination;    ///< "convergence", "no_convergence" or "failure"
  std::string message;        ///< Ceres' reason for stopping
  std::size_t residuals = 0;  ///< m: measured points of all curves
  double rss = 0;             ///< sum of squared residuals at the solution, N^2
  double initial_rms = 0, final_rms = 0;  ///< sqrt(RSS / m) at the start and at the end, N
  std::vector<MeasuredSpread> measured;   ///< per curve, on FitCurve::x
  std::vector<std::vector<double>> initial_curves, fitted_curves;  ///< simulated, N
};

/// Called after every iteration with a line of progress ("iteration 3: rms 1.2e-3 N ...").
using FitProgress = std::function<void(const std::string&)>;

/// Runs the fit. Throws InputError or DivergenceError (fit_model.hpp) when the simulation
/// at the initial values fails; a failure at a trial point only rejects that step.
FitResult run_fit(const FitSpec& spec, const FitProgress& progress = {});

}  // namespace finseg
