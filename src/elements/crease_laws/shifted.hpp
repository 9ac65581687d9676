// A crease law moved along its angle: the rest angle placed where a pattern wants it, or
// carried from the flat sheet to the folded one over a time (folding by simulation,
// docs/folding.md). M(phi, t) = M_law(phi - shift(t)). A carried rest angle moves so that
// the tangent of its half grows linearly with time: the fold angles of a flat-foldable
// degree-4 vertex keep constant ratios of their half-angle tangents (Huffman), so such
// targets stay compatible with rigid folding all the way.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "elements/crease_laws/wrapped.hpp"

namespace finseg {

class ShiftedCreaseLaw final : public WrappedCreaseLaw {
 public:
  /// The rest angle r(t) (rad in the law's angle, |r| < pi) goes from `rest_start` (t = 0)
  /// to `rest_end` (t >= `ramp`) with tan(r/2) linear in t; `ramp` <= 0: rest_end at all
  /// times. t is the law's time (s, or the static solver's load scale). The shift is taken
  /// from the law's rest angle for a fresh history.
  ShiftedCreaseLaw(std::shared_ptr<const CreaseLaw> law, double rest_start, double rest_end,
                   double ramp);
  /// Resting at `rest` (rad in the law's angle) at all times.
  ShiftedCreaseLaw(std::shared_ptr<const CreaseLaw> law, double rest)
      : ShiftedCreaseLaw(std::move(law), rest, rest, 0) {}
  MomentSample evaluate(double phi, const ElementHistory& history, double t) const override;
  double rest_angle(const ElementHistory& history, double t) const override;
  double energy(double phi, const ElementHistory& history, double t) const override;
  MomentEnergy evaluate_with_energy(double phi, const ElementHistory& history,
                                    double t) const override;
  std::string describe() const override;
  double shift(double t) const;  ///< rad

 private:
  double law_rest_;               ///< the law's rest angle for a fresh history, rad
  double rest_start_, rest_end_;  ///< rad
  double ramp_;
  double half_start_, half_end_;  ///< tan(rest / 2) at the start and at the end
};

}  // namespace finseg
