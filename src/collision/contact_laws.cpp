// Contact parameter helper and validation.
#include "collision/contact_laws.hpp"

#include <fmt/format.h>
#include <cmath>

#include "core/error.hpp"

namespace finseg {

ContactSuggestion suggest_contact(double reduced_mass, double gravity, double depth,
                                  double exponent, double load_factor, double damping_ratio) {
  auto positive = [](double v, const char* name) {
    if (!(v > 0) || !std::isfinite(v))
      throw InputError("<api>", name, fmt::format("must be positive and finite, got {}", v));
  };
  positive(reduced_mass, "reduced_mass");
  positive(gravity, "gravity");
  positive(depth, "depth");
  positive(load_factor, "load_factor");
  if (!(exponent >= 1) || !std::isfinite(exponent))
    throw InputError("<api>", "exponent", fmt::format("must be >= 1, got {}", exponent));
  if (!(damping_ratio >= 0) || !std::isfinite(damping_ratio))
    throw InputError("<api>", "damping_ratio", fmt::format("must be >= 0, got {}", damping_ratio));
  ContactSuggestion s;
  const double load = load_factor * reduced_mass * gravity;
  s.stiffness = load / std::pow(depth, exponent);
  const double k_lin = exponent * load / depth;  // dF/d(delta) at delta = depth
  s.damping = damping_ratio * 2 * std::sqrt(k_lin * reduced_mass);
  s.damping_depth = depth;
  s.tangential_stiffness = k_lin;
  s.tangential_damping = 2 * std::sqrt(k_lin * reduced_mass);
  s.period = 2 * kPi * std::sqrt(reduced_mass / k_lin);
  return s;
}

double step3_slope(double x, double x0, double h0, double x1, double h1) {
  if (x <= x0 || x >= x1) return 0;
  const double s = (x - x0) / (x1 - x0);
  return (h1 - h0) * 6 * s * (1 - s) / (x1 - x0);
}

NormalForceSlopes normal_force_slopes(const ContactDef& c, double delta, double delta_dot,
                                      double v0) {
  NormalForceSlopes r;
  if (!(delta > 0)) return r;
  const double elastic = c.stiffness * std::pow(delta, c.exponent);
  const double elastic_slope = c.stiffness * c.exponent * std::pow(delta, c.exponent - 1);
  if (c.damping_law == ContactDamping::Impact) {
    const double damping = step3(delta, 0.0, 0.0, c.damping_depth, c.damping);
    r.d_delta =
        elastic_slope + step3_slope(delta, 0.0, 0.0, c.damping_depth, c.damping) * delta_dot;
    r.d_rate = damping;
  } else {
    const double v = std::max(std::abs(v0), c.min_impact_speed);
    const double chi = hysteresis_factor(c.damping_law, c.restitution) / v;
    r.d_delta = elastic_slope * (1 + chi * delta_dot);
    r.d_rate = elastic * chi;
  }
  return r;
}

double friction_coefficient_slope(const ContactDef& c, double v) {
  if (v <= c.stiction_speed)
    return step3_slope(v, -c.stiction_speed, -c.mu_static, c.stiction_speed, c.mu_static);
  return step3_slope(v, c.stiction_speed, c.mu_static, c.friction_speed, c.mu_dynamic);
}

FrictionSlopes continuous_friction_slopes(const ContactDef& c, double fn, const Vec3& v_t,
                                          double lag_speed, FrictionSlope slope) {
  // f = -fn g(v2) v_t with g = mu(v) / v: df/dv_t = -fn (g I + 2 g' v_t v_t^T).
  const double v2 = v_t.squaredNorm();
  const double vs = c.stiction_speed;
  const bool lagged = lag_speed >= 0;
  const double w = lagged ? friction_weakening(c, lag_speed) : 1.0;
  double g, g_slope;  // g and dg / d(v2)
  if (v2 < 1e-6 * vs * vs) {
    g = w * (c.mu_static / vs) * (1.5 - 0.5 * v2 / (vs * vs));
    g_slope = -w * (c.mu_static / vs) * 0.5 / (vs * vs);
  } else {
    const double v = std::sqrt(v2);
    double mu, mu_slope;
    if (lagged) {
      mu = w * rising_friction(c, v);
      mu_slope = v <= vs ? w * step3_slope(v, -vs, -c.mu_static, vs, c.mu_static) : 0.0;
    } else {
      mu = friction_coefficient(c, v);
      mu_slope = friction_coefficient_slope(c, v);
    }
    g = mu / v;
    g_slope = (mu_slope / v - mu / v2) / (2 * v);
  }
  FrictionSlopes r;
  r.f = -fn * g * v_t;
  r.d_fn = -g * v_t;
  // mu(v) / v never rises with v for these laws (g_slope <= 0): the secant drops the
  // along-slip term that makes the tangent flatter than it.
  r.secant_differs = slope == FrictionSlope::Secant && fn != 0 && g_slope * v2 != 0;
  if (r.secant_differs) g_slope = 0;
  r.d_vt = -fn * (g * Mat3::Identity() + 2 * g_slope * v_t * v_t.transpose());
  return r;
}

void validate_contact(const ContactDef& c, const std::string& file) {
  if (!c.enabled) return;
  auto fail = [&](const char* field, const std::string& what) {
    throw InputError(file, std::string("contact.") + field, what);
  };
  auto finite = [&](double v, const char* field) {
    if (!std::isfinite(v)) fail(field, fmt::format("must be finite, got {}", v));
  };
  finite(c.stiffness, "stiffness");
  if (!(c.stiffness > 0)) fail("stiffness", fmt::format("must be > 0 N/m^e, got {}", c.stiffness));
  finite(c.exponent, "exponent");
  if (!(c.exponent >= 1)) fail("exponent", fmt::format("must be >= 1, got {}", c.exponent));
  finite(c.damping, "damping");
  if (!(c.damping >= 0)) fail("damping", fmt::format("must be >= 0 N s/m, got {}", c.damping));
  finite(c.damping_depth, "damping_depth");
  if (!(c.damping_depth > 0))
    fail("damping_depth", fmt::format("must be > 0 m, got {}", c.damping_depth));
  if (c.damping_law != ContactDamping::Impact) {
    finite(c.restitution, "restitution");
    if (!(c.restitution > 0 && c.restitution <= 1))
      fail("restitution", fmt::format("must be in (0, 1], got {}", c.restitution));
    finite(c.min_impact_speed, "min_impact_speed");
    if (!(c.min_impact_speed > 0))
      fail("min_impact_speed", fmt::format("must be > 0 m/s, got {}", c.min_impact_speed));
  }
  if (c.friction != FrictionModel::None) {
    finite(c.mu_static, "mu_static");
    finite(c.mu_dynamic, "mu_dynamic");
    if (!(c.mu_static >= 0)) fail("mu_static", fmt::format("must be >= 0, got {}", c.mu_static));
    if (!(c.mu_dynamic >= 0)) fail("mu_dynamic", fmt::format("must be >= 0, got {}", c.mu_dynamic));
    if (c.mu_dynamic > c.mu_static)
      fail("mu_dynamic",
           fmt::format("must be <= mu_static = {}, got {}", c.mu_static, c.mu_dynamic));
    finite(c.stiction_speed, "stiction_speed");
    finite(c.friction_speed, "friction_speed");
    if (!(c.stiction_speed > 0))
      fail("stiction_speed", fmt::format("must be > 0 m/s, got {}", c.stiction_speed));
    if (!(c.friction_speed > c.stiction_speed))
      fail("friction_speed", fmt::format("must be > stiction_speed = {} m/s, got {}",
                                         c.stiction_speed, c.friction_speed));
  }
  if (c.friction == FrictionModel::Anchor) {
    finite(c.tangential_stiffness, "tangential_stiffness");
    finite(c.tangential_damping, "tangential_damping");
    if (!(c.tangential_stiffness > 0))
      fail("tangential_stiffness",
           fmt::format("must be > 0 N/m for friction: anchor, got {}", c.tangential_stiffness));
    if (!(c.tangential_damping >= 0))
      fail("tangential_damping", fmt::format("must be >= 0 N s/m, got {}", c.tangential_damping));
  }
  if (c.panel_exclusion < 0)
    fail("panel_exclusion", fmt::format("must be >= 0 elements, got {}", c.panel_exclusion));
  if (c.samples_per_edge < 2 || c.samples_per_edge > 16)
    fail("samples_per_edge", fmt::format("must be in 2..16 points, got {}", c.samples_per_edge));
  if (c.crease_zone) {
    finite(*c.crease_zone, "crease_zone");
    if (!(*c.crease_zone >= 0))
      fail("crease_zone", fmt::format("must be >= 0 m, got {}", *c.crease_zone));
  }
  finite(c.margin, "margin");
  if (!(c.margin >= 0)) fail("margin", fmt::format("must be >= 0 m, got {}", c.margin));
  for (std::size_t g = 0; g < c.groups.size(); ++g)
    for (int p : c.groups[g])
      if (p < 0) fail("groups", fmt::format("group {}: panel indices must be >= 0, got {}", g, p));
}

}  // namespace finseg
