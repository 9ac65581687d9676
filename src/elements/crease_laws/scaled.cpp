#include "elements/crease_laws/scaled.hpp"

#include <fmt/format.h>

#include <utility>

namespace finseg {

ScaledCreaseLaw::ScaledCreaseLaw(std::shared_ptr<const CreaseLaw> law, double share)
    : WrappedCreaseLaw(std::move(law)), share_(share) {}

MomentSample ScaledCreaseLaw::evaluate(double phi, const ElementHistory& history, double t) const {
  const MomentSample m = law_->evaluate(phi, history, t);
  return {share_ * m.moment, share_ * m.stiffness};
}

double ScaledCreaseLaw::rest_angle(const ElementHistory& history, double t) const {
  return law_->rest_angle(history, t);
}

double ScaledCreaseLaw::energy(double phi, const ElementHistory& history, double t) const {
  return share_ * law_->energy(phi, history, t);
}

MomentEnergy ScaledCreaseLaw::evaluate_with_energy(double phi, const ElementHistory& history,
                                                   double t) const {
  const MomentEnergy m = law_->evaluate_with_energy(phi, history, t);
  return {{share_ * m.sample.moment, share_ * m.sample.stiffness}, share_ * m.energy};
}

std::string ScaledCreaseLaw::describe() const {
  return fmt::format("{:.6g} x {}", share_, law_->describe());
}

}  // namespace finseg
