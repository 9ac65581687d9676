#include "elements/crease_laws/shifted.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/types.hpp"

namespace finseg {

ShiftedCreaseLaw::ShiftedCreaseLaw(std::shared_ptr<const CreaseLaw> law, double shift_start,
                                   double shift_end, double ramp)
    : WrappedCreaseLaw(std::move(law)),
      start_(shift_start),
      end_(shift_end),
      ramp_(ramp),
      rest_(law_->rest_angle(ElementHistory{}, 0)) {}

double ShiftedCreaseLaw::shift(double t) const {
  if (ramp_ <= 0 || t >= ramp_) return end_;
  const double lambda = std::clamp(t / ramp_, 0.0, 1.0);
  const double half =
      (1 - lambda) * std::tan((rest_ + start_) / 2) + lambda * std::tan((rest_ + end_) / 2);
  return 2 * std::atan(half) - rest_;
}

MomentSample ShiftedCreaseLaw::evaluate(double phi, const ElementHistory& history, double t) const {
  return law_->evaluate(phi - shift(t), history, t);
}

double ShiftedCreaseLaw::rest_angle(const ElementHistory& history, double t) const {
  return law_->rest_angle(history, t) + shift(t);
}

double ShiftedCreaseLaw::energy(double phi, const ElementHistory& history, double t) const {
  return law_->energy(phi - shift(t), history, t);
}

std::string ShiftedCreaseLaw::describe() const {
  if (ramp_ <= 0)
    return fmt::format("{} shifted by {:.6g} deg", law_->describe(), end_ / kDegToRad);
  return fmt::format("{} shifted from {:.6g} to {:.6g} deg over {:.6g}", law_->describe(),
                     start_ / kDegToRad, end_ / kDegToRad, ramp_);
}

}  // namespace finseg
