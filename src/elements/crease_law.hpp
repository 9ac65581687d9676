// Crease laws: the moment about a crease line as a function of its fold angle and history.
#pragma once

#include <string>

#include "model/state.hpp"

namespace finseg {

/// Moment M = dU/dalpha (N m) needed to hold the crease at fold angle alpha, and its
/// tangent stiffness dM/dalpha (N m/rad).
struct MomentSample {
  double moment = 0;
  double stiffness = 0;
};

/// Interface of every crease law. alpha is the exact signed fold angle (rad), measured from
/// the flat sheet; `history` holds the crease's opening count; t is the simulated time (s).
class CreaseLaw {
 public:
  virtual ~CreaseLaw() = default;
  virtual MomentSample evaluate(double alpha, const ElementHistory& history, double t) const = 0;
  /// Angle of zero moment for the given history (used to report and to build rest states).
  virtual double rest_angle(const ElementHistory& history, double t) const = 0;
  virtual std::string describe() const = 0;
};

/// M = k (alpha - rest): the linear crease.
class LinearCreaseLaw final : public CreaseLaw {
 public:
  LinearCreaseLaw(double stiffness, double rest_angle);
  MomentSample evaluate(double alpha, const ElementHistory& history, double t) const override;
  double rest_angle(const ElementHistory& history, double t) const override;
  std::string describe() const override;

 private:
  double k_, rest_;
};

}  // namespace finseg
