// A crease law carried by part of a crease: the moment of another law times a share (e.g.
// the length of one segment side over the crease length the law was identified for).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "elements/crease_laws/wrapped.hpp"

namespace finseg {

class ScaledCreaseLaw final : public WrappedCreaseLaw {
 public:
  /// `share` > 0 multiplies moment, stiffness and energy; angles and history are the law's.
  ScaledCreaseLaw(std::shared_ptr<const CreaseLaw> law, double share);
  MomentSample evaluate(double phi, const ElementHistory& history, double t) const override;
  double rest_angle(const ElementHistory& history, double t) const override;
  double energy(double phi, const ElementHistory& history, double t) const override;
  MomentEnergy evaluate_with_energy(double phi, const ElementHistory& history,
                                    double t) const override;
  std::string describe() const override;

 private:
  double share_;
};

}  // namespace finseg
