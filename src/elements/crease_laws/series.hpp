// A crease law in series with a linear bending spring: the fold of the crease itself and the
// bending of the sheet next to it share one measured angle, phi = phi_law + phi_spring, and
// carry one moment (docs/stiffness.md, "Creases on cell sides"). Each evaluation solves
// M_law(phi_law) = k (phi - phi_law) for phi_law.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "elements/crease_laws/wrapped.hpp"

namespace finseg {

class SeriesCreaseLaw final : public WrappedCreaseLaw {
 public:
  /// `spring` > 0: the bending spring's stiffness, N m/rad. The law's stiffness must stay
  /// above -spring (a law softer than that would snap inside the pair); the opening history
  /// is the law's, counted on the pair's whole angle.
  SeriesCreaseLaw(std::shared_ptr<const CreaseLaw> law, double spring);
  MomentSample evaluate(double phi, const ElementHistory& history, double t) const override;
  double rest_angle(const ElementHistory& history, double t) const override;
  double energy(double phi, const ElementHistory& history, double t) const override;
  MomentEnergy evaluate_with_energy(double phi, const ElementHistory& history,
                                    double t) const override;
  std::string describe() const override;
  /// The law's share of the angle, phi_law (rad).
  double law_angle(double phi, const ElementHistory& history, double t) const;

 private:
  struct Split {
    double law_angle;     // phi_law, rad
    MomentSample at_law;  // the law there
  };
  Split split(double phi, const ElementHistory& history, double t) const;
  std::optional<Split> newton_from_phi(double phi, const MomentSample& at_phi,
                                       const ElementHistory& history, double t) const;
  Split safeguarded(double phi, const MomentSample& at_phi, const ElementHistory& history,
                    double t) const;
  MomentSample pair_sample(double phi, const Split& s) const;
  double pair_energy(double phi, const Split& s, const ElementHistory& history, double t) const;
  double spring_;
};

}  // namespace finseg
