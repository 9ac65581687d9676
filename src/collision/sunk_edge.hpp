// Distance of a point that has sunk past the target plate's mid-plane (on the far side from
// the side it keeps) while it lies beside the target polygon: over the polygon such a point is
// pushed back to its side from `side * h < 0` deep, beside it the rounded rim's distance
// |(delta, h)| would push it on through. Both meet at the polygon's boundary only where h = 0,
// so a sunk point crossing an edge met a jump of twice its force (docs/contact.md, "A sunk
// point beside an edge"). This distance joins them with a continuous slope:
//
//   f(delta, h) = rho - 2 chi(delta) h^2 / rho,   rho = sqrt(delta^2 + h^2),
//
// chi = 1 - 3 t^2 + 2 t^3 (t = delta / L, L the two half thicknesses), 0 beyond L. At delta = 0
// it is -|h| = side * h (over the polygon's value) with slope 0 along delta and 1 towards the
// kept side; at h = 0 it is delta with the rim's slope; beyond L it is the rim's distance.
#pragma once

#include <cmath>

// Eigen/Dense must come before the AutoDiff header that kinematics.hpp pulls in.
#include "core/types.hpp"

#include "elements/kinematics.hpp"

namespace finseg {

/// f and its slopes by the in-plane offset delta (> 0) and the height h.
template <class T>
struct SunkEdgeDistance {
  T f, f_delta, f_h;
};

/// The blend chi(delta) of the sunk distance and its first two slopes (0 beyond L).
struct SunkEdgeBlend {
  double chi = 0, chi_1 = 0, chi_2 = 0;
};

/// chi's Hermite cubic on t = delta / L in [0, 1] (value 1 and slope 0 at the polygon,
/// value 0 and slope 0 at L); its slopes by delta.
inline SunkEdgeBlend sunk_edge_blend(double delta, double L) {
  const double t = delta / L;
  if (!(t < 1)) return {};
  return {1 - t * t * (3 - 2 * t), 6 * t * (t - 1) / L, (12 * t - 6) / (L * L)};
}

/// f, df/ddelta and df/dh for scalar T (double or an automatic-differentiation type);
/// delta > 0 (beside the polygon), L the two plates' half thicknesses summed.
template <class T>
SunkEdgeDistance<T> sunk_edge_distance(const T& delta, const T& h, double L) {
  using std::sqrt;
  const SunkEdgeBlend b = sunk_edge_blend(value_of(delta), L);
  const T chi = lift(delta, b.chi, b.chi_1), chi_1 = lift(delta, b.chi_1, b.chi_2);
  const T rho = sqrt(delta * delta + h * h);
  const T q = h * h / rho;
  const T q_delta = -h * h * delta / (rho * rho * rho);
  const T q_h = h * (T(2) * delta * delta + h * h) / (rho * rho * rho);
  SunkEdgeDistance<T> d;
  d.f = rho - T(2) * chi * q;
  d.f_delta = delta / rho - T(2) * (chi_1 * q + chi * q_delta);
  d.f_h = h / rho - T(2) * chi * q_h;
  return d;
}

/// Second slopes of f (doubles, for the closed-form Jacobian): f_dd, f_dh, f_hh.
struct SunkEdgeCurvature {
  double f_dd = 0, f_dh = 0, f_hh = 0;
};

inline SunkEdgeCurvature sunk_edge_curvature(double delta, double h, double L) {
  const SunkEdgeBlend b = sunk_edge_blend(delta, L);
  const double r2 = delta * delta + h * h, rho = std::sqrt(r2);
  const double r3 = r2 * rho, r5 = r3 * r2;
  const double q = h * h / rho;
  const double q_d = -h * h * delta / r3;
  const double q_h = h * (2 * delta * delta + h * h) / r3;
  const double q_dd = h * h * (2 * delta * delta - h * h) / r5;
  const double q_dh = h * delta * (h * h - 2 * delta * delta) / r5;
  const double q_hh = delta * delta * (2 * delta * delta - h * h) / r5;
  SunkEdgeCurvature c;
  c.f_dd = h * h / r3 - 2 * (b.chi_2 * q + 2 * b.chi_1 * q_d + b.chi * q_dd);
  c.f_dh = -delta * h / r3 - 2 * (b.chi_1 * q_h + b.chi * q_dh);
  c.f_hh = delta * delta / r3 - 2 * b.chi * q_hh;
  return c;
}

}  // namespace finseg
