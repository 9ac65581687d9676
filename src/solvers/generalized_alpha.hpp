// Generalized-alpha parameters of Chung & Hulbert (1993) from the spectral radius at
// infinite frequency (docs/solvers.md).
#pragma once

namespace finseg {

/// alpha_m, alpha_f, gamma, beta of the scheme
///   (1 - alpha_m) a_{n+1} + alpha_m a_n = (1 - alpha_f) vdot_{n+1} + alpha_f vdot_n.
struct AlphaParameters {
  double alpha_m = 0, alpha_f = 0, gamma = 0.5, beta = 0.25;
};

/// Chung-Hulbert's optimal parameters for rho_inf in [0, 1]: second order, unconditionally
/// stable, high-frequency dissipation maximal for the given low-frequency dissipation.
AlphaParameters chung_hulbert(double rho_inf);

}  // namespace finseg
