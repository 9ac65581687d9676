#include "elements/crease_laws/series.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace finseg {

SeriesCreaseLaw::SeriesCreaseLaw(std::shared_ptr<const CreaseLaw> law, double spring)
    : WrappedCreaseLaw(std::move(law)), spring_(spring) {}

double SeriesCreaseLaw::law_angle(double phi, const ElementHistory& history, double t) const {
  // g(x) = M_law(x) - k (phi - x) rises with x (g' = K_law + k > 0). Its root lies between
  // phi and phi - M_law(phi) / k for a law whose moment rises with the angle; safeguarded
  // Newton inside that bracket, widened if the law is not monotone there.
  const auto g = [&](double x) {
    const MomentSample m = law_->evaluate(x, history, t);
    return std::pair{m.moment - spring_ * (phi - x), m.stiffness + spring_};
  };
  double lo = phi, hi = phi - law_->evaluate(phi, history, t).moment / spring_;
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
  return x;
}

MomentSample SeriesCreaseLaw::evaluate(double phi, const ElementHistory& history, double t) const {
  const double x = law_angle(phi, history, t);
  const double K = law_->evaluate(x, history, t).stiffness;
  // dM/dphi of two springs in series: k K / (k + K).
  return {spring_ * (phi - x), spring_ * K / (spring_ + K)};
}

double SeriesCreaseLaw::rest_angle(const ElementHistory& history, double t) const {
  return law_->rest_angle(history, t);
}

double SeriesCreaseLaw::energy(double phi, const ElementHistory& history, double t) const {
  const double x = law_angle(phi, history, t);
  return law_->energy(x, history, t) + 0.5 * spring_ * (phi - x) * (phi - x);
}

std::string SeriesCreaseLaw::describe() const {
  return fmt::format("{} in series with {:.6g} N m/rad of sheet bending", law_->describe(),
                     spring_);
}

}  // namespace finseg
