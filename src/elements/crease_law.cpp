#include "elements/crease_law.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace finseg {

LinearCreaseLaw::LinearCreaseLaw(double stiffness, double rest_angle)
    : k_(stiffness), rest_(rest_angle) {
  if (!(stiffness >= 0)) {
    throw InputError("<api>", "crease.stiffness", "must be >= 0 N m/rad");
  }
}

MomentSample LinearCreaseLaw::evaluate(double alpha, const ElementHistory&, double) const {
  return {k_ * (alpha - rest_), k_};
}

double LinearCreaseLaw::rest_angle(const ElementHistory&, double) const {
  return rest_;
}

std::string LinearCreaseLaw::describe() const {
  return fmt::format("linear k={} N m/rad rest={} rad", k_, rest_);
}

}  // namespace finseg
