#include "elements/crease_laws/series.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace finseg {

SeriesCreaseLaw::SeriesCreaseLaw(std::shared_ptr<const CreaseLaw> law, double spring)
    : WrappedCreaseLaw(std::move(law)), spring_(spring) {}

// g(x) = M_law(x) - k (phi - x) rises with x (g' = K_law + k > 0); g(phi) = M_law(phi).
SeriesCreaseLaw::Split SeriesCreaseLaw::split(double phi, const ElementHistory& history,
                                              double t) const {
  const MomentSample at_phi = law_->evaluate(phi, history, t);
  if (const auto s = newton_from_phi(phi, at_phi, history, t)) return *s;
  return safeguarded(phi, at_phi, history, t);
}

// Newton from phi: one step is exact for a linear law, a few serve a smooth one, and each
// costs one evaluation of the law (the safeguarded search costs three more to start).
std::optional<SeriesCreaseLaw::Split> SeriesCreaseLaw::newton_from_phi(
    double phi, const MomentSample& at_phi, const ElementHistory& history, double t) const {
  constexpr int kSteps = 8;
  double x = phi;
  MomentSample m = at_phi;
  for (int it = 0; it < kSteps; ++it) {
    const double gx = m.moment - spring_ * (phi - x), dg = m.stiffness + spring_;
    if (gx == 0) return Split{x, m};
    if (!(dg > 0) || !std::isfinite(gx)) return std::nullopt;
    const double dx = gx / dg;
    if (std::abs(dx) <= 1e-15 * std::max(1.0, std::abs(x))) return Split{x, m};
    x -= dx;
    m = law_->evaluate(x, history, t);
  }
  return std::nullopt;
}

// The root lies between phi and phi - M_law(phi) / k for a law whose moment rises with the
// angle; safeguarded Newton inside that bracket, widened if the law is not monotone there.
SeriesCreaseLaw::Split SeriesCreaseLaw::safeguarded(double phi, const MomentSample& at_phi,
                                                    const ElementHistory& history, double t) const {
  const auto g = [&](double y) {
    const MomentSample my = law_->evaluate(y, history, t);
    return std::pair{my.moment - spring_ * (phi - y), my.stiffness + spring_};
  };
  double lo = phi, hi = phi - at_phi.moment / spring_;
  if (lo > hi) std::swap(lo, hi);
  for (int k = 0; k < 60 && g(lo).first > 0; ++k) lo -= (hi - lo) + 1e-3;
  for (int k = 0; k < 60 && g(hi).first < 0; ++k) hi += (hi - lo) + 1e-3;
  // Newton where it shrinks the bracket fast enough, else bisection (rtsafe).
  double x = 0.5 * (lo + hi), dx_old = hi - lo, dx = dx_old;
  for (int it = 0; it < 200; ++it) {
    const auto [gx, dg] = g(x);
    if (gx == 0) break;
    (gx > 0 ? hi : lo) = x;
    const double newton = x - gx / dg;
    if (!(newton > lo && newton < hi) || std::abs(2 * gx) > std::abs(dx_old * dg)) {
      dx_old = dx;
      dx = 0.5 * (hi - lo);
      x = lo + dx;
    } else {
      dx_old = dx;
      dx = gx / dg;
      x = newton;
    }
    if (std::abs(dx) <= 1e-15 * std::max(1.0, std::abs(x))) break;
  }
  return {x, law_->evaluate(x, history, t)};
}

double SeriesCreaseLaw::law_angle(double phi, const ElementHistory& history, double t) const {
  return split(phi, history, t).law_angle;
}

MomentSample SeriesCreaseLaw::pair_sample(double phi, const Split& s) const {
  // dM/dphi of two springs in series: k K / (k + K).
  const double K = s.at_law.stiffness;
  return {spring_ * (phi - s.law_angle), spring_ * K / (spring_ + K)};
}

double SeriesCreaseLaw::pair_energy(double phi, const Split& s, const ElementHistory& history,
                                    double t) const {
  const double bend = phi - s.law_angle;  // the spring's share of the angle
  return law_->energy(s.law_angle, history, t) + 0.5 * spring_ * bend * bend;
}

MomentSample SeriesCreaseLaw::evaluate(double phi, const ElementHistory& history, double t) const {
  return pair_sample(phi, split(phi, history, t));
}

MomentEnergy SeriesCreaseLaw::evaluate_with_energy(double phi, const ElementHistory& history,
                                                   double t) const {
  const Split s = split(phi, history, t);
  return {pair_sample(phi, s), pair_energy(phi, s, history, t)};
}

double SeriesCreaseLaw::rest_angle(const ElementHistory& history, double t) const {
  return law_->rest_angle(history, t);
}

double SeriesCreaseLaw::energy(double phi, const ElementHistory& history, double t) const {
  return pair_energy(phi, split(phi, history, t), history, t);
}

std::string SeriesCreaseLaw::describe() const {
  return fmt::format("{} in series with {:.6g} N m/rad of sheet bending", law_->describe(),
                     spring_);
}

}  // namespace finseg
