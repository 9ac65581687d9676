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
  /// The rest angle r(t) = rest + shift(t) goes from rest + `shift_start` (t = 0) to rest +
  /// `shift_end` (t >= `ramp`) with tan(r/2) linear in t (rad in the law's angle, |r| < pi);
  /// `ramp` <= 0: shift_end at all times. t is the law's time (s, or the static solver's
  /// load scale).
  ShiftedCreaseLaw(std::shared_ptr<const CreaseLaw> law, double shift_start, double shift_end,
                   double ramp);
  /// Constant shift.
  ShiftedCreaseLaw(std::shared_ptr<const CreaseLaw> law, double shift)
      : ShiftedCreaseLaw(std::move(law), shift, shift, 0) {}
  MomentSample evaluate(double phi, const ElementHistory& history, double t) const override;
  double rest_angle(const ElementHistory& history, double t) const override;
  double energy(double phi, const ElementHistory& history, double t) const override;
  std::string describe() const override;
  double shift(double t) const;  ///< rad

 private:
  double start_, end_, ramp_;
  double rest_;  ///< the law's rest angle for a fresh history, rad
};

}  // namespace finseg
