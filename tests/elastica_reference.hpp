// Independent references for the validation tests: the elastica of a cantilever under a
// vertical dead tip load (Bisshopp & Drucker 1945) through elliptic integrals, the circular
// arc of a cantilever under an end moment, and the Euler-Bernoulli cantilever eigenvalues.
// Nothing here uses finseg code.
#pragma once

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

namespace finseg::reference {

/// Tip of an inextensible, shear-free cantilever of length L under a dead load P normal to
/// its undeformed axis, as fractions of L, and the tip slope.
struct ElasticaTip {
  double horizontal = 0;  ///< shortening of the span along the undeformed axis, / L
  double vertical = 0;    ///< deflection along the load, / L
  double tip_angle = 0;   ///< slope of the tip relative to the undeformed axis, rad
};

namespace detail {

// Modulus k and lower amplitude phi1 of the elliptic integrals for tip slope theta0:
// 1 + sin(theta) = 2 k^2 sin^2(phi), so theta = 0 maps to sin(phi1) = 1 / (k sqrt 2).
struct EllipticArgs {
  double k, phi1;
};

inline EllipticArgs elliptic_args(double theta0) {
  const double k = std::sqrt(0.5 * (1 + std::sin(theta0)));
  return {k, std::asin(1 / (k * std::sqrt(2.0)))};
}

// sqrt(alpha) as a function of the tip slope: K(k) - F(phi1, k).
inline double sqrt_alpha_of_tip_angle(double theta0) {
  const EllipticArgs a = elliptic_args(theta0);
  return boost::math::ellint_1(a.k) - boost::math::ellint_1(a.k, a.phi1);
}

}  // namespace detail

/// Elastica under a vertical dead tip load, alpha = P L^2 / (E I) > 0. The tip slope theta0
/// solves sqrt(alpha) = K(k) - F(phi1, k) (bracketing root finder); then
/// horizontal = 1 - sqrt(2 sin(theta0) / alpha) and
/// vertical = 1 - 2 (E(k) - E(phi1, k)) / sqrt(alpha).
inline ElasticaTip elastica_tip_load(double alpha) {
  if (!(alpha > 0)) throw std::invalid_argument("elastica_tip_load: alpha must be > 0");
  const double target = std::sqrt(alpha);
  auto f = [&](double theta0) { return detail::sqrt_alpha_of_tip_angle(theta0) - target; };
  // At theta0 -> 0 the left side tends to 0; at theta0 -> pi/2 it grows like ln(1 / k'):
  // pi/2 - 1e-6 (k' ~ 5e-7) covers alpha up to about 200 and keeps k < 1 in doubles.
  if (alpha > 200) throw std::invalid_argument("elastica_tip_load: alpha must be <= 200");
  std::uintmax_t iterations = 200;
  const auto bracket =
      boost::math::tools::toms748_solve(f, 1e-12, std::numbers::pi / 2 - 1e-6,
                                        boost::math::tools::eps_tolerance<double>(50), iterations);
  const double theta0 = 0.5 * (bracket.first + bracket.second);
  const detail::EllipticArgs a = detail::elliptic_args(theta0);
  ElasticaTip tip;
  tip.tip_angle = theta0;
  tip.horizontal = 1 - std::sqrt(2 * std::sin(theta0) / alpha);
  tip.vertical = 1 - 2 * (boost::math::ellint_2(a.k) - boost::math::ellint_2(a.k, a.phi1)) / target;
  return tip;
}

/// Tip of a cantilever of length L bent into a circular arc by an end moment M: with
/// curvature kappa = M / (E I), the tip lies at (sin(kappa L), 1 - cos(kappa L)) / kappa
/// from the clamp (along the axis, towards the centre of curvature), returned / L.
struct ArcTip {
  double along = 0;   ///< / L
  double across = 0;  ///< / L
};

inline ArcTip arc_tip(double curvature_times_length) {
  const double c = curvature_times_length;
  if (std::abs(c) < 1e-8) return {1.0, 0.5 * c};
  return {std::sin(c) / c, (1 - std::cos(c)) / c};
}

/// n-th root (n = 1, 2, ...) of the Euler-Bernoulli cantilever frequency equation
/// 1 + cos(x) cosh(x) = 0: the natural frequencies are x_n^2 / (2 pi L^2) sqrt(EI / (rho A)).
inline double cantilever_beta_l(int n) {
  if (n < 1) throw std::invalid_argument("cantilever_beta_l: n must be >= 1");
  // Written as cos(x) + 1 / cosh(x) = 0 to stay well scaled; root n lies in
  // ((n - 1/2) pi, n pi) for n = 1 and near (n - 1/2) pi beyond.
  auto f = [](double x) { return std::cos(x) + 1 / std::cosh(x); };
  const double pi = std::numbers::pi;
  std::uintmax_t iterations = 200;
  const auto bracket =
      boost::math::tools::toms748_solve(f, (n - 1) * pi + 0.5 * pi * (n == 1 ? 1.0 : 0.5), n * pi,
                                        boost::math::tools::eps_tolerance<double>(50), iterations);
  return 0.5 * (bracket.first + bracket.second);
}

/// Angular frequency of mode n of the Euler-Bernoulli cantilever of length L (m), bending
/// rigidity EI (N m^2) and mass per length rho_A (kg/m), rad/s.
inline double cantilever_omega(int n, double L, double EI, double rho_A) {
  const double bl = cantilever_beta_l(n);
  return bl * bl / (L * L) * std::sqrt(EI / rho_A);
}

}  // namespace finseg::reference
