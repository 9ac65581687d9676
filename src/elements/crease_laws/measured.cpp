#include "elements/crease_laws/measured.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/warnings.hpp"

namespace finseg {

namespace {

std::vector<double> to_radians(const std::vector<double>& deg) {
  std::vector<double> r;
  r.reserve(deg.size());
  for (double d : deg) r.push_back(d * kDegToRad);
  return r;
}

}  // namespace

MomentCurve::MomentCurve(const CreaseCurve& curve, SplineEnds ends)
    : spline_(to_radians(curve.angle_deg), curve.moment, ends, SplineExtrapolation::Linear) {}

MeasuredCreaseLaw::MeasuredCreaseLaw(const CreaseData& data, const MeasuredLawOptions& options,
                                     const std::string& file, const std::string& field)
    : source_(data.source), options_(options) {
  if (data.curves.empty()) throw InputError(file, field, "crease data hold no curve");
  if (options.openings_before < 0) {
    throw InputError(file, field + ".openings_before",
                     fmt::format("{} must be >= 0", options.openings_before));
  }
  validate_opening_rule(options.rule, file, field);
  pressing_times_ = data.pressing_times();
  for (double p : pressing_times_) {
    std::vector<MomentCurve> curves;
    for (const CreaseCurve* c : data.curves_at(p)) curves.emplace_back(*c, options.ends);
    curves_.push_back(std::move(curves));
  }
  const std::string measured = fmt::format("{}", fmt::join(pressing_times_, ", "));
  if (!options.pressing_time) {
    if (pressing_times_.size() > 1) {
      throw InputError(
          file, field + ".pressing_time",
          fmt::format("required: {} has several pressing times ({} s)", data.source, measured));
    }
    ia_ = ib_ = 0;
    w_ = 0;
    return;
  }
  const double p = *options.pressing_time;
  if (!std::isfinite(p) || p < pressing_times_.front() || p > pressing_times_.back()) {
    throw InputError(file, field + ".pressing_time",
                     fmt::format("{} s outside the measured pressing times {} s of {}", p, measured,
                                 data.source));
  }
  const auto it = std::lower_bound(pressing_times_.begin(), pressing_times_.end(), p);
  ib_ = static_cast<size_t>(it - pressing_times_.begin());
  if (*it == p) {
    ia_ = ib_;
    w_ = 0;
  } else {
    ia_ = ib_ - 1;
    w_ = (p - pressing_times_[ia_]) / (pressing_times_[ib_] - pressing_times_[ia_]);
  }
}

int MeasuredCreaseLaw::opening_of(const ElementHistory& history) const {
  return options_.openings_before + std::max(0, history.openings) + 1;
}

CubicSpline::Sample MeasuredCreaseLaw::opening_moment(double theta, int opening) const {
  check_range(theta, opening);
  auto one = [&](size_t ip) {
    const std::vector<MomentCurve>& c = curves_[ip];
    const size_t k = static_cast<size_t>(std::min<int>(opening, static_cast<int>(c.size()))) - 1;
    return c[k].at(theta);
  };
  CubicSpline::Sample s = one(ia_);
  if (ib_ != ia_) {
    const CubicSpline::Sample b = one(ib_);
    s.value = (1 - w_) * s.value + w_ * b.value;
    s.slope = (1 - w_) * s.slope + w_ * b.slope;
    s.curvature = (1 - w_) * s.curvature + w_ * b.curvature;
  }
  return s;
}

void MeasuredCreaseLaw::check_range(double theta, int opening) const {
  if (warned_.load(std::memory_order_relaxed)) return;
  for (size_t ip : {ia_, ib_}) {
    const std::vector<MomentCurve>& c = curves_[ip];
    const MomentCurve& m =
        c[static_cast<size_t>(std::min<int>(opening, static_cast<int>(c.size()))) - 1];
    // Round-off and finite-difference probes at the end points do not count as outside.
    constexpr double kSlack = 1e-6;  // rad
    if (theta < m.theta_min() - kSlack || theta > m.theta_max() + kSlack) {
      if (!warned_.exchange(true)) {
        warn(fmt::format(
            "crease law {}: opening angle {:.4g} deg outside the "
            "measured {:.4g}..{:.4g} deg (pressing time {} s, opening {}); continuing "
            "linearly with the end slope (warned once)",
            source_, theta / kDegToRad, m.theta_min() / kDegToRad, m.theta_max() / kDegToRad,
            pressing_times_[ip], std::min<int>(opening, static_cast<int>(c.size()))));
      }
      return;
    }
  }
}

MomentSample MeasuredCreaseLaw::evaluate(double phi, const ElementHistory& history, double) const {
  const CubicSpline::Sample s = opening_moment(opening_angle(phi), opening_of(history));
  // theta = pi - phi: dU/dphi = -dU/dtheta = -M, d(-M)/dphi = dM/dtheta.
  return {-s.value, s.slope};
}

double MeasuredCreaseLaw::energy(double phi, const ElementHistory& history, double) const {
  const double theta = opening_angle(phi);
  const int n = opening_of(history);
  auto one = [&](size_t ip) {
    const std::vector<MomentCurve>& c = curves_[ip];
    return c[static_cast<size_t>(std::min<int>(n, static_cast<int>(c.size()))) - 1].integral(theta);
  };
  // U = integral of M dtheta, so that dU/dphi = -M.
  double u = one(ia_);
  if (ib_ != ia_) u = (1 - w_) * u + w_ * one(ib_);
  return u;
}

double MeasuredCreaseLaw::rest_angle(const ElementHistory& history, double) const {
  // First zero crossing of M(theta) from below, searched over the measured range widened by
  // one radian each side; refined by bisection.
  const int n = opening_of(history);
  double lo = 1e300, hi = -1e300;
  for (size_t ip : {ia_, ib_}) {
    for (const MomentCurve& c : curves_[ip]) {
      lo = std::min(lo, c.theta_min());
      hi = std::max(hi, c.theta_max());
    }
  }
  lo -= 1.0;
  hi += 1.0;
  auto M = [&](double th) {
    // Plain evaluation without the range warning.
    auto one = [&](size_t ip) {
      const std::vector<MomentCurve>& c = curves_[ip];
      return c[static_cast<size_t>(std::min<int>(n, static_cast<int>(c.size()))) - 1].at(th).value;
    };
    double v = one(ia_);
    if (ib_ != ia_) v = (1 - w_) * v + w_ * one(ib_);
    return v;
  };
  const int steps = 720;
  double a = lo, fa = M(a);
  for (int i = 1; i <= steps; ++i) {
    const double b = lo + (hi - lo) * i / steps, fb = M(b);
    if (fa <= 0 && fb > 0) {
      double l = a, r = b;
      for (int k = 0; k < 200 && r - l > 1e-15; ++k) {
        const double c = 0.5 * (l + r);
        (M(c) <= 0 ? l : r) = c;
      }
      return kPi - 0.5 * (l + r);
    }
    a = b;
    fa = fb;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

std::string MeasuredCreaseLaw::describe() const {
  return fmt::format("measured {} ({} ends, pressing time {} s, {} opening(s) before)", source_,
                     to_string(options_.ends),
                     options_.pressing_time ? fmt::format("{}", *options_.pressing_time)
                                            : fmt::format("{}", pressing_times_.front()),
                     options_.openings_before);
}

RelaxingCreaseLaw::RelaxingCreaseLaw(std::shared_ptr<const CreaseLaw> base, double coefficient,
                                     double time_constant, double age, double reference_age,
                                     const std::string& file, const std::string& field)
    : WrappedCreaseLaw(std::move(base)),
      c_(coefficient),
      tau_(time_constant),
      age_(age),
      age_ref_(reference_age) {
  if (!law_) throw InputError(file, field, "needs a base crease law");
  if (!std::isfinite(c_)) throw InputError(file, field + ".coefficient_deg", "must be finite");
  if (!(tau_ > 0) || !std::isfinite(tau_)) {
    throw InputError(file, field + ".time_constant_s", fmt::format("{} must be > 0 s", tau_));
  }
  if (!(age_ >= 0) || !std::isfinite(age_)) {
    throw InputError(file, field + ".age_s", fmt::format("{} must be >= 0 s", age_));
  }
  if (!(age_ref_ >= 0) || !std::isfinite(age_ref_)) {
    throw InputError(file, field + ".reference_age_s", fmt::format("{} must be >= 0 s", age_ref_));
  }
}

double RelaxingCreaseLaw::shift(double t) const {
  const double since = std::max(0.0, age_ + t);
  return c_ * (std::log1p(since / tau_) - std::log1p(age_ref_ / tau_));
}

double RelaxingCreaseLaw::signed_shift(const ElementHistory& history, double t) const {
  if (law_->direction_relative()) return shift(t);
  return law_->rest_angle(history, t) < 0 ? -shift(t) : shift(t);
}

MomentSample RelaxingCreaseLaw::evaluate(double phi, const ElementHistory& history,
                                         double t) const {
  return law_->evaluate(phi + signed_shift(history, t), history, t);
}

double RelaxingCreaseLaw::rest_angle(const ElementHistory& history, double t) const {
  return law_->rest_angle(history, t) - signed_shift(history, t);
}

double RelaxingCreaseLaw::energy(double phi, const ElementHistory& history, double t) const {
  return law_->energy(phi + signed_shift(history, t), history, t);
}

MomentEnergy RelaxingCreaseLaw::evaluate_with_energy(double phi, const ElementHistory& history,
                                                     double t) const {
  return law_->evaluate_with_energy(phi + signed_shift(history, t), history, t);
}

std::string RelaxingCreaseLaw::describe() const {
  return fmt::format("{} relaxing by {} deg per e-fold (tau {} s, age {} s, reference {} s)",
                     law_->describe(), c_ / kDegToRad, tau_, age_, age_ref_);
}

}  // namespace finseg
