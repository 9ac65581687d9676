// Measured crease laws (paper eq. 17): a C^2 cubic spline of moment against opening angle
// through the measured points, one curve per pressing time and opening count, and the
// logarithmic relaxation of the rest angle with time since folding.
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/cubic_spline.hpp"
#include "elements/crease_law.hpp"
#include "elements/crease_laws/crease_data.hpp"
#include "elements/crease_laws/wrapped.hpp"

namespace finseg {

/// One measured curve M(theta): theta the opening angle in rad, M >= 0 the moment that holds
/// the crease open (N m). Interpolating cubic spline inside the measured range; outside it
/// the straight line through the end point with the end slope.
class MomentCurve {
 public:
  MomentCurve(const CreaseCurve& curve, SplineEnds ends);
  CubicSpline::Sample at(double theta) const { return spline_.sample(theta); }
  /// Integral of M from theta_min() to theta (J), exact for the spline and its continuation.
  double integral(double theta) const { return spline_.integral(theta); }
  double theta_min() const { return spline_.x_min(); }
  double theta_max() const { return spline_.x_max(); }

 private:
  CubicSpline spline_;
};

struct MeasuredLawOptions {
  /// Pressing time of the crease (s). Linear interpolation between the two nearest measured
  /// pressing times; must lie inside the measured range. May be left out when the data have
  /// a single pressing time.
  std::optional<double> pressing_time;
  SplineEnds ends = SplineEnds::NotAKnot;
  int openings_before = 0;  ///< completed openings before the run (added to the history's)
  OpeningRule rule;
};

/// The measured crease law. With n = openings_before + history.openings + 1 the current
/// opening, each bracketing pressing time uses its curve of opening min(n, last measured);
/// M(theta) = (1 - w) M_a(theta) + w M_b(theta), w = (p - p_a)/(p_b - p_a). In the crease's
/// direction: moment dU/dphi = -M(pi - phi), stiffness dM(pi - phi)/dtheta. Outside a curve's
/// angle range it continues linearly and warns once on stderr (more than 1e-6 rad outside).
class MeasuredCreaseLaw final : public CreaseLaw {
 public:
  /// `file`/`field` name where the options came from, for InputError messages.
  MeasuredCreaseLaw(const CreaseData& data, const MeasuredLawOptions& options,
                    const std::string& file = "<api>", const std::string& field = "crease");
  MomentSample evaluate(double phi, const ElementHistory& history, double t) const override;
  double rest_angle(const ElementHistory& history, double t) const override;  ///< NaN: none
  double energy(double phi, const ElementHistory& history, double t) const override;
  OpeningRule opening_rule() const override { return options_.rule; }
  bool direction_relative() const override { return true; }
  std::vector<std::string> data_files() const override { return {source_}; }
  std::string describe() const override;

  /// M(theta) and dM/dtheta in the data's terms (opening angle theta, rad) for a given
  /// opening count (1-based, including openings_before).
  CubicSpline::Sample opening_moment(double theta, int opening) const;
  /// Whether the one-time out-of-range warning has been given.
  bool warned() const { return warned_.load(); }

 private:
  int opening_of(const ElementHistory& history) const;
  void check_range(double theta, int opening) const;

  std::string source_;
  MeasuredLawOptions options_;
  std::vector<double> pressing_times_;
  std::vector<std::vector<MomentCurve>> curves_;  ///< [pressing time][opening - 1]
  size_t ia_ = 0, ib_ = 0;                        ///< bracketing pressing times
  double w_ = 0;                                  ///< weight of ib_
  mutable std::atomic<bool> warned_{false};
};

/// Relaxation of a fold (paper/polymer films open slowly after folding): the rest opening
/// angle grows logarithmically with the time since folding,
///     theta_rest(t) = theta_rest(t_ref) + c ln((1 + (age + t)/tau) / (1 + age_ref/tau)),
/// applied to any law as a shift of the angle: M(phi, t) = M_base(phi + Delta(t)) (for a law
/// in the signed angle, phi - sign(rest) Delta: the fold opens towards flat), with
/// Delta(t) = c ln((1 + (age + t)/tau) / (1 + age_ref/tau)). c: rad per e-fold of time (> 0:
/// the crease opens), tau > 0 (s), age >= 0: age of the crease at t = 0 (s), age_ref >= 0:
/// age at which the base law holds unshifted (s; usually the age when it was measured).
class RelaxingCreaseLaw final : public WrappedCreaseLaw {
 public:
  RelaxingCreaseLaw(std::shared_ptr<const CreaseLaw> base, double coefficient, double time_constant,
                    double age, double reference_age, const std::string& file = "<api>",
                    const std::string& field = "relaxation");
  double shift(double t) const;  ///< Delta(t), rad
  MomentSample evaluate(double phi, const ElementHistory& history, double t) const override;
  double rest_angle(const ElementHistory& history, double t) const override;
  double energy(double phi, const ElementHistory& history, double t) const override;
  MomentEnergy evaluate_with_energy(double phi, const ElementHistory& history,
                                    double t) const override;
  std::string describe() const override;

 private:
  /// The shift in the base law's angle: +Delta for direction-relative laws; for laws in
  /// the signed angle, the opening direction is taken from the sign of the base's rest angle.
  double signed_shift(const ElementHistory& history, double t) const;

  double c_, tau_, age_, age_ref_;
};

}  // namespace finseg
