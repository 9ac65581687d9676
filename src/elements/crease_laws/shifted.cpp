#include "elements/crease_laws/shifted.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/types.hpp"

namespace finseg {

ShiftedCreaseLaw::ShiftedCreaseLaw(std::shared_ptr<const CreaseLaw> law, double rest_start,
                                   double rest_end, double ramp)
    : WrappedCreaseLaw(std::move(law)),
      law_rest_(law_->rest_angle(ElementHistory{}, 0)),
      rest_start_(rest_start),
      rest_end_(rest_end),
      ramp_(ramp),
      half_start_(std::tan(rest_start / 2)),
      half_end_(std::tan(rest_end / 2)) {}

double ShiftedCreaseLaw::shift(double t) const {
  if (ramp_ <= 0 || t >= ramp_) return rest_end_ - law_rest_;
  const double lambda = std::max(t / ramp_, 0.0);
  return 2 * std::atan((1 - lambda) * half_start_ + lambda * half_end_) - law_rest_;
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

// One call of the wrapped law, so that a law that solves for both (a series law) solves once.
MomentEnergy ShiftedCreaseLaw::evaluate_with_energy(double phi, const ElementHistory& history,
                                                    double t) const {
  return law_->evaluate_with_energy(phi - shift(t), history, t);
}

std::string ShiftedCreaseLaw::describe() const {
  if (ramp_ <= 0) {
    return fmt::format("{} resting at {:.6g} deg", law_->describe(), rest_end_ / kDegToRad);
  }
  return fmt::format("{} resting from {:.6g} to {:.6g} deg over {:.6g}", law_->describe(),
                     rest_start_ / kDegToRad, rest_end_ / kDegToRad, ramp_);
}

}  // namespace finseg
