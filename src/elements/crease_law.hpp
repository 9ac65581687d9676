// Crease laws: the moment about a crease line as a function of its fold angle and history.
//
// Angle convention (docs/crease-data.md). The element measures the exact signed fold angle
// alpha (rad) of E relative to F about F's y axis, 0 for the flat sheet, unwrapped over
// turns. A crease has a fold direction s = +1 or -1: CreaseDef::direction, or the sign of
// CreaseDef::initial_fold_angle (+1 when that is 0). A law is written either
//  - in the signed angle alpha itself (direction_relative() == false; LinearCreaseLaw,
//    whose rest angle then carries the sign of the fold), or
//  - in the crease's own direction, phi = s * alpha (direction_relative() == true; measured
//    laws), so that one law serves peaks and valleys alike. The element maps back:
//    M_alpha = s * M_phi, dM_alpha/dalpha = dM_phi/dphi.
// Measured data use the paper's opening angle theta = pi - phi (0: folded flat shut, pi:
// flat sheet), the dihedral angle between the two flaps, in degrees in files.
#pragma once

#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/crease_def.hpp"
#include "model/state.hpp"

namespace finseg {

/// Moment M = dU/dphi (N m) needed to hold the crease at fold angle phi, and its tangent
/// stiffness dM/dphi (N m/rad).
struct MomentSample {
  double moment = 0;
  double stiffness = 0;
};

/// A moment sample and the stored energy U(phi) (J) at the same angle.
struct MomentEnergy {
  MomentSample sample;
  double energy = 0;
};

/// When a crease counts as opened and closed again (ElementHistory::openings), in terms of
/// the opening angle theta = pi - phi, rad. Opened: theta rises above `opened_above`;
/// the opening is complete (openings += 1) when theta then falls below `closed_below`.
struct OpeningRule {
  double opened_above = 90 * kDegToRad;
  double closed_below = 30 * kDegToRad;
};

/// Interface of every crease law. `phi` is the law's angle (rad, see above): alpha, or
/// s * alpha for direction-relative laws; `history` holds the crease's opening count; t is
/// the simulated time (s; in static runs the solver's load or drive parameter).
class CreaseLaw {
 public:
  virtual ~CreaseLaw() = default;
  virtual MomentSample evaluate(double phi, const ElementHistory& history, double t) const = 0;
  /// Angle of zero moment for the given history (used to report and to build rest states).
  virtual double rest_angle(const ElementHistory& history, double t) const = 0;
  virtual std::string describe() const = 0;
  /// Stored energy U(phi) (J) with dU/dphi = evaluate().moment, up to a constant that may
  /// depend on history and time. The default integrates the moment from the rest angle by
  /// Gauss-Legendre quadrature; laws with a closed form override it.
  virtual double energy(double phi, const ElementHistory& history, double t) const;
  /// evaluate() and energy() at one angle (a force element wants both); a law that solves for
  /// an inner angle overrides it to solve once, and a law made from another passes it on.
  virtual MomentEnergy evaluate_with_energy(double phi, const ElementHistory& history,
                                            double t) const {
    return {evaluate(phi, history, t), energy(phi, history, t)};
  }
  /// Thresholds for counting openings (commit_crease_history).
  virtual OpeningRule opening_rule() const { return {}; }
  /// True: the law's angle is phi = s * alpha (the crease's own direction); false: alpha.
  virtual bool direction_relative() const { return false; }
  /// Data files the law was read from (as opened), for provenance; none by default.
  virtual std::vector<std::string> data_files() const { return {}; }
};

/// Fold direction of a crease: CreaseDef::direction where given, else the sign of its
/// initial fold angle, +1 when flat.
inline double crease_direction(const CreaseDef& crease) {
  if (crease.direction != 0) return crease.direction < 0 ? -1.0 : 1.0;
  return crease.initial_fold_angle < 0 ? -1.0 : 1.0;
}

/// The sign the element applies to alpha before calling the law: s for direction-relative
/// laws, +1 for laws in the signed angle.
inline double law_direction(const CreaseDef& crease) {
  return crease.law && crease.law->direction_relative() ? crease_direction(crease) : 1.0;
}

/// Opening angle theta = pi - phi (rad) of the fold angle phi in the crease's direction.
inline double opening_angle(double phi) {
  return kPi - phi;
}

/// M = k (alpha - rest): the linear crease, in the signed fold angle. `rest_angle` is the
/// signed fold angle of zero moment (rad), e.g. the initial fold angle for a crease at rest.
class LinearCreaseLaw final : public CreaseLaw {
 public:
  LinearCreaseLaw(double stiffness, double rest_angle, OpeningRule rule = {});
  MomentSample evaluate(double phi, const ElementHistory& history, double t) const override;
  double rest_angle(const ElementHistory& history, double t) const override;
  double energy(double phi, const ElementHistory& history, double t) const override;
  OpeningRule opening_rule() const override { return rule_; }
  std::string describe() const override;

 private:
  double k_, rest_;
  OpeningRule rule_;
};

/// Checks an opening rule: 0 <= closed_below < opened_above, finite. `field` names the
/// source of the values in messages.
void validate_opening_rule(const OpeningRule& rule, const std::string& file,
                           const std::string& field);

}  // namespace finseg
