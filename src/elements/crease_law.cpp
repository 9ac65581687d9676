#include "elements/crease_law.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"

namespace finseg {

double CreaseLaw::energy(double phi, const ElementHistory& history, double t) const {
  // U(phi) = integral of M from the rest angle to phi: 8-point Gauss-Legendre on sub-intervals
  // of at most 0.1 rad. Exact for polynomial moments up to degree 15 per sub-interval.
  static constexpr double xg[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                   0.9602898564975363};
  static constexpr double wg[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                   0.1012285362903763};
  double a = rest_angle(history, t);
  if (!std::isfinite(a)) a = 0;
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(phi - a) / 0.1)));
  const double h = (phi - a) / pieces;
  double u = 0;
  for (int p = 0; p < pieces; ++p) {
    const double c = a + (p + 0.5) * h;
    for (int g = 0; g < 4; ++g) {
      const double d = 0.5 * h * xg[g];
      u += 0.5 * h * wg[g] *
           (evaluate(c - d, history, t).moment + evaluate(c + d, history, t).moment);
    }
  }
  return u;
}

void validate_opening_rule(const OpeningRule& rule, const std::string& file,
                           const std::string& field) {
  if (!(std::isfinite(rule.opened_above) && std::isfinite(rule.closed_below) &&
        rule.closed_below >= 0 && rule.closed_below < rule.opened_above &&
        rule.opened_above <= 2 * kPi)) {
    throw InputError(file, field,
                     fmt::format("need 0 <= closed_below_deg < opened_above_deg <= 360, got "
                                 "{} and {} deg",
                                 rule.closed_below / kDegToRad, rule.opened_above / kDegToRad));
  }
}

LinearCreaseLaw::LinearCreaseLaw(double stiffness, double rest_angle, OpeningRule rule)
    : k_(stiffness), rest_(rest_angle), rule_(rule) {
  if (!(stiffness >= 0) || !std::isfinite(stiffness)) {
    throw InputError("<api>", "crease.stiffness", "must be finite and >= 0 N m/rad");
  }
  if (!std::isfinite(rest_angle)) {
    throw InputError("<api>", "crease.rest_angle", "must be finite (rad)");
  }
  validate_opening_rule(rule, "<api>", "crease.opening_rule");
}

MomentSample LinearCreaseLaw::evaluate(double phi, const ElementHistory&, double) const {
  return {k_ * (phi - rest_), k_};
}

double LinearCreaseLaw::rest_angle(const ElementHistory&, double) const {
  return rest_;
}

double LinearCreaseLaw::energy(double phi, const ElementHistory&, double) const {
  return 0.5 * k_ * (phi - rest_) * (phi - rest_);
}

std::string LinearCreaseLaw::describe() const {
  return fmt::format("linear k={} N m/rad rest={} deg", k_, rest_ / kDegToRad);
}

}  // namespace finseg
