// Contact force laws (paper eqs. 18-19), templated on the scalar so that the contact kernel
// runs with double and with forward-mode autodiff. docs/contact.md describes them.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

// Eigen/Dense must come before the AutoDiff header that kinematics.hpp pulls in.
#include "core/types.hpp"

#include "elements/kinematics.hpp"
#include "model/contact_def.hpp"

namespace finseg {

/// Adams STEP with a cubic: h0 for x <= x0, h1 for x >= x1, h0 + (h1-h0) s^2 (3 - 2 s) between.
template <class T>
T step3(const T& x, double x0, double h0, double x1, double h1) {
  if (value_of(x) <= x0) return T(h0);
  if (value_of(x) >= x1) return T(h1);
  const T s = (x - T(x0)) / T(x1 - x0);
  return T(h0) + T(h1 - h0) * s * s * (T(3) - T(2) * s);
}

/// Hysteresis factor chi of the HC / LN / Flores laws: F = K delta^e (1 + chi delta_dot / v0).
inline double hysteresis_factor(ContactDamping law, double cr) {
  switch (law) {
    case ContactDamping::HuntCrossley:
      return 1.5 * (1 - cr);
    case ContactDamping::LankaraniNikravesh:
      return 0.75 * (1 - cr * cr);
    case ContactDamping::Flores:
      return 1.6 * (1 - cr) / cr;
    case ContactDamping::Impact:
      break;
  }
  return 0;
}

/// Normal force of a whole-face contact (eq. 18) at penetration delta > 0 and penetration
/// rate delta_dot (> 0 approaching). v0: penetration rate when the contact began (hysteresis
/// laws). Never negative.
template <class T>
T normal_force(const ContactDef& c, const T& delta, const T& delta_dot, double v0) {
  using std::pow;
  if (value_of(delta) <= 0) return T(0);
  const T elastic = T(c.stiffness) * pow(delta, c.exponent);
  T f;
  if (c.damping_law == ContactDamping::Impact) {
    f = elastic + step3(delta, 0.0, 0.0, c.damping_depth, c.damping) * delta_dot;
  } else {
    const double v = std::max(std::abs(v0), c.min_impact_speed);
    f = elastic * (T(1) + T(hysteresis_factor(c.damping_law, c.restitution) / v) * delta_dot);
  }
  if (value_of(f) <= 0) return T(0);
  return f;
}

/// Elastic energy stored at penetration delta, J.
inline double contact_energy(const ContactDef& c, double delta) {
  if (delta <= 0) return 0;
  return c.stiffness * std::pow(delta, c.exponent + 1) / (c.exponent + 1);
}

/// Adams continuous friction coefficient at slip speed v >= 0: odd cubic STEP from 0 to mu_s
/// on [0, v_s], cubic STEP from mu_s to mu_d on [v_s, v_d], mu_d beyond.
template <class T>
T friction_coefficient(const ContactDef& c, const T& v) {
  if (value_of(v) <= c.stiction_speed)
    return step3(v, -c.stiction_speed, -c.mu_static, c.stiction_speed, c.mu_static);
  return step3(v, c.stiction_speed, c.mu_static, c.friction_speed, c.mu_dynamic);
}

/// Adams' law factored as mu(v) = rising(v) * weakening(v): `rising_friction` is the odd
/// STEP from 0 to mu_s on [0, v_s], mu_s beyond (never falls); `friction_weakening` is 1 up to
/// v_s and the STEP down to mu_d / mu_s at v_d (the falling, Stribeck branch).
template <class T>
T rising_friction(const ContactDef& c, const T& v) {
  if (value_of(v) <= c.stiction_speed)
    return step3(v, -c.stiction_speed, -c.mu_static, c.stiction_speed, c.mu_static);
  return T(c.mu_static);
}
inline double friction_weakening(const ContactDef& c, double v) {
  if (!(c.mu_static > 0) || v <= c.stiction_speed) return 1;
  return step3(v, c.stiction_speed, 1.0, c.friction_speed, c.mu_dynamic / c.mu_static);
}

/// Friction force of the continuous law: -F_n mu(|v_t|) v_t / |v_t|, smooth through v_t = 0
/// (mu(v)/v tends to 3 mu_s / (2 v_s)). With `lag_speed` >= 0 (the point's slip speed at the
/// last accepted step) the falling branch is taken there: mu = rising(|v_t|) *
/// weakening(lag_speed), so that the force never falls as the unknown speed grows
/// (docs/contact.md, "Friction").
template <class T>
Vec3T<T> continuous_friction(const ContactDef& c, const T& fn, const Vec3T<T>& v_t,
                             double lag_speed = -1) {
  using std::sqrt;
  const T v2 = v_t.squaredNorm();
  const double vs = c.stiction_speed;
  const double w = lag_speed >= 0 ? friction_weakening(c, lag_speed) : 1.0;
  T ratio;  // mu(v) / v
  if (value_of(v2) < 1e-6 * vs * vs) {
    // Odd cubic about 0: mu = mu_s (3/2 x - 1/2 x^3), x = v / v_s.
    ratio = T(w * c.mu_static / vs) * (T(1.5) - T(0.5) * v2 / T(vs * vs));
  } else {
    const T v = sqrt(v2);
    ratio = (lag_speed >= 0 ? T(w) * rising_friction(c, v) : friction_coefficient(c, v)) / v;
  }
  return -fn * ratio * v_t;
}

// Slopes of the laws above for the closed-form contact Jacobian (collision/contact_jacobian.*);
// each takes the same branches as its law, decided on the same values.

/// d step3 / dx at x.
double step3_slope(double x, double x0, double h0, double x1, double h1);

/// Partial derivatives of normal_force by delta > 0 and delta_dot where the force is
/// positive (where normal_force clamps it to zero they are zero: the caller knows).
struct NormalForceSlopes {
  double d_delta = 0, d_rate = 0;
};
NormalForceSlopes normal_force_slopes(const ContactDef& c, double delta, double delta_dot,
                                      double v0);

/// d friction_coefficient / dv at slip speed v >= 0.
double friction_coefficient_slope(const ContactDef& c, double v);

/// What d_vt of FrictionSlopes holds: the tangent df/dv_t, or the secant -fn (mu(v)/v) I,
/// which differs from it along the slip only (where the tangent is flatter: on the plateau of
/// mu, not at all) and serves Newton as its iteration matrix (docs/solvers.md, "Friction's
/// secant").
enum class FrictionSlope { Tangent, Secant };

/// continuous_friction f(fn, v_t) with df/dfn and df/dv_t (or its secant, `slope`).
struct FrictionSlopes {
  Vec3 f = Vec3::Zero();
  Vec3 d_fn = Vec3::Zero();
  Mat3 d_vt = Mat3::Zero();
  bool secant_differs = false;  ///< the secant was asked for and is not the tangent here
};
FrictionSlopes continuous_friction_slopes(const ContactDef& c, double fn, const Vec3& v_t,
                                          double lag_speed = -1,
                                          FrictionSlope slope = FrictionSlope::Tangent);

/// Contact parameters derived for a gram-scale part (docs/contact.md, "Choosing values").
struct ContactSuggestion {
  double stiffness = 0;             ///< K, N/m^e
  double damping = 0;               ///< c_max, N s/m (critical damping of the linearised contact)
  double damping_depth = 0;         ///< d, m
  double tangential_stiffness = 0;  ///< k_t, N/m
  double tangential_damping = 0;    ///< c_t, N s/m
  double period = 0;                ///< period of the linearised contact vibration, s
};

/// K such that a face carries `load_factor` times the part's weight m g at the penetration
/// `depth`; c_max = `damping_ratio` times critical damping of the reduced mass on the
/// linearised stiffness at that depth; d = depth; k_t = the same linearised stiffness,
/// c_t = critical for it. Throws InputError on non-positive input.
ContactSuggestion suggest_contact(double reduced_mass, double gravity, double depth,
                                  double exponent = 1.5, double load_factor = 100,
                                  double damping_ratio = 1.0);

/// Checks every field of `c` (when enabled); throws InputError(file, "contact.<field>", ...).
void validate_contact(const ContactDef& c, const std::string& file);

}  // namespace finseg
