// Crease laws: measured spline law against exact polynomials, energy against finite
// differences, pressing-time and opening selection, extrapolation warning, relaxation.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>

#include "core/error.hpp"
#include "elements/crease_law.hpp"
#include "elements/crease_laws/crease_data.hpp"
#include "elements/crease_laws/measured.hpp"

using namespace finseg;

namespace crease_law_test {

// A cubic moment-angle curve in degrees: M(theta_deg) = a + b u + c u^2 + d u^3, u = deg/100.
struct Cubic {
  double a, b, c, d;
  double M(double deg) const {
    const double u = deg / 100;
    return a + b * u + c * u * u + d * u * u * u;
  }
  double dM_dtheta(double theta_rad) const {  // per radian
    const double u = theta_rad / kDegToRad / 100;
    return (b + 2 * c * u + 3 * d * u * u) / (100 * kDegToRad);
  }
};

CreaseCurve curve_of(const Cubic& p, double pressing, int opening,
                     const std::vector<double>& angles) {
  CreaseCurve c;
  c.pressing_time = pressing;
  c.opening = opening;
  for (double a : angles) {
    c.angle_deg.push_back(a);
    c.moment.push_back(p.M(a));
  }
  return c;
}

const std::vector<double> kAngles = {20, 35, 60, 70, 100, 140};
const Cubic kP1{0.001, 0.004, -0.0005, 0.0003};  // first opening
const Cubic kP2{0.002, 0.006, 0.001, 0.0002};    // second opening
const Cubic kQ1{0.003, 0.010, -0.001, 0.0004};   // longer pressing, first opening

CreaseData family() {
  CreaseData d;
  d.source = "family";
  d.curves = {curve_of(kP1, 10, 1, kAngles), curve_of(kP2, 10, 2, kAngles),
              curve_of(kQ1, 40, 1, kAngles)};
  return d;
}

double fd_energy(const CreaseLaw& law, double phi, const ElementHistory& h, double t) {
  const double e = 1e-7;
  return (law.energy(phi + e, h, t) - law.energy(phi - e, h, t)) / (2 * e);
}

double fd_moment(const CreaseLaw& law, double phi, const ElementHistory& h, double t) {
  const double e = 1e-7;
  return (law.evaluate(phi + e, h, t).moment - law.evaluate(phi - e, h, t).moment) / (2 * e);
}

TEST(CreaseLaw, LinearMomentIsEnergyDerivative) {
  const LinearCreaseLaw law(0.02, 1.3);
  const ElementHistory h;
  for (double phi = -4; phi < 4; phi += 0.37) {
    EXPECT_NEAR(law.evaluate(phi, h, 0).moment, 0.02 * (phi - 1.3), 1e-15);
    EXPECT_NEAR(law.evaluate(phi, h, 0).moment, fd_energy(law, phi, h, 0), 1e-9);
  }
  EXPECT_THROW(LinearCreaseLaw law(-1, 0), InputError);
}

TEST(CreaseLaw, DefaultEnergyIntegratesTheMoment) {
  // A law without its own energy: the base-class quadrature must still give dU/dphi = M.
  struct Sine final : CreaseLaw {
    MomentSample evaluate(double phi, const ElementHistory&, double) const override {
      return {0.01 * std::sin(phi - 0.5), 0.01 * std::cos(phi - 0.5)};
    }
    double rest_angle(const ElementHistory&, double) const override { return 0.5; }
    std::string describe() const override { return "sine"; }
  } law;
  const ElementHistory h;
  for (double phi = -2; phi < 3; phi += 0.31) {
    EXPECT_NEAR(law.energy(phi, h, 0), 0.01 * (1 - std::cos(phi - 0.5)), 1e-13);
  }
}

TEST(CreaseLaw, MeasuredSingleCurveReproducesCubicData) {
  CreaseData d;
  d.source = "cubic";
  d.curves = {curve_of(kP1, 0, 1, kAngles)};
  const MeasuredCreaseLaw law(d, {});
  const ElementHistory h;
  for (double deg = 20; deg <= 140; deg += 2.5) {
    const double theta = deg * kDegToRad, phi = kPi - theta;
    const MomentSample m = law.evaluate(phi, h, 0);
    // Opening angle theta = pi - phi; the law gives dU/dphi = -M(theta).
    EXPECT_NEAR(m.moment, -kP1.M(deg), 1e-14) << deg;
    EXPECT_NEAR(m.stiffness, kP1.dM_dtheta(theta), 1e-13) << deg;
    EXPECT_NEAR(m.moment, fd_energy(law, phi, h, 0), 1e-9) << deg;
    EXPECT_NEAR(m.stiffness, fd_moment(law, phi, h, 0), 1e-7) << deg;
  }
  EXPECT_FALSE(law.warned());
}

TEST(CreaseLaw, MeasuredNaturalEndsPassThroughPoints) {
  CreaseData d;
  d.source = "pts";
  CreaseCurve c;
  c.angle_deg = {10, 30, 45, 90, 120};
  c.moment = {0.0, 0.004, 0.005, 0.011, 0.02};
  d.curves = {c};
  MeasuredLawOptions o;
  o.ends = SplineEnds::Natural;
  const MeasuredCreaseLaw law(d, o);
  const ElementHistory h;
  for (size_t i = 0; i < c.angle_deg.size(); ++i) {
    EXPECT_NEAR(law.evaluate(kPi - c.angle_deg[i] * kDegToRad, h, 0).moment, -c.moment[i], 1e-15);
  }
  // Zero moment at 10 deg opening with positive slope: that is the rest angle.
  EXPECT_NEAR(law.rest_angle(h, 0), kPi - 10 * kDegToRad, 1e-12);
}

TEST(CreaseLaw, MeasuredOutsideRangeLinearWithWarningOnce) {
  CreaseData d;
  d.source = "cubic.csv";
  d.curves = {curve_of(kP1, 0, 1, kAngles)};
  const MeasuredCreaseLaw law(d, {});
  const ElementHistory h;
  testing::internal::CaptureStderr();
  const double lo = 20 * kDegToRad, hi = 140 * kDegToRad;
  for (double theta : {lo - 0.2, hi + 0.3, lo - 0.1}) {
    const double end = theta < lo ? lo : hi;
    const MomentSample m = law.evaluate(kPi - theta, h, 0);
    EXPECT_NEAR(m.moment, -(kP1.M(end / kDegToRad) + kP1.dM_dtheta(end) * (theta - end)), 1e-14);
    EXPECT_NEAR(m.stiffness, kP1.dM_dtheta(end), 1e-13);
    EXPECT_NEAR(m.moment, fd_energy(law, kPi - theta, h, 0), 1e-9);
  }
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_TRUE(law.warned());
  size_t count = 0;
  for (size_t p = err.find("warning"); p != std::string::npos; p = err.find("warning", p + 1)) {
    ++count;
  }
  EXPECT_EQ(count, 1u) << err;
  EXPECT_NE(err.find("cubic.csv"), std::string::npos);
}

TEST(CreaseLaw, FamilyInterpolatesPressingTimeAndFollowsOpenings) {
  const CreaseData d = family();
  MeasuredLawOptions o;
  o.pressing_time = 20;  // one third of the way from 10 s to 40 s
  const MeasuredCreaseLaw law(d, o);
  ElementHistory h;
  const double deg = 77, theta = deg * kDegToRad, phi = kPi - theta;
  const double w = (20.0 - 10.0) / (40.0 - 10.0);
  // First opening: curves (10 s, 1) and (40 s, 1).
  EXPECT_NEAR(law.evaluate(phi, h, 0).moment, -((1 - w) * kP1.M(deg) + w * kQ1.M(deg)), 1e-14);
  EXPECT_NEAR(law.evaluate(phi, h, 0).stiffness,
              (1 - w) * kP1.dM_dtheta(theta) + w * kQ1.dM_dtheta(theta), 1e-12);
  // Second opening: 10 s has curve 2; 40 s has only curve 1, which it keeps using.
  h.openings = 1;
  EXPECT_NEAR(law.evaluate(phi, h, 0).moment, -((1 - w) * kP2.M(deg) + w * kQ1.M(deg)), 1e-14);
  h.openings = 7;  // beyond the last measured opening: the last curve
  EXPECT_NEAR(law.evaluate(phi, h, 0).moment, -((1 - w) * kP2.M(deg) + w * kQ1.M(deg)), 1e-14);
  EXPECT_NEAR(law.evaluate(phi, h, 0).moment, fd_energy(law, phi, h, 0), 1e-9);
  // openings_before shifts the count.
  o.openings_before = 1;
  const MeasuredCreaseLaw later(d, o);
  EXPECT_NEAR(later.evaluate(phi, ElementHistory{}, 0).moment,
              -((1 - w) * kP2.M(deg) + w * kQ1.M(deg)), 1e-14);
  // Exactly at a measured pressing time: that curve alone.
  o.openings_before = 0;
  o.pressing_time = 40;
  const MeasuredCreaseLaw at40(d, o);
  EXPECT_NEAR(at40.evaluate(phi, ElementHistory{}, 0).moment, -kQ1.M(deg), 1e-14);
}

TEST(CreaseLaw, FamilyRejectsBadPressingTime) {
  const CreaseData d = family();
  MeasuredLawOptions o;
  EXPECT_THROW(MeasuredCreaseLaw law(d, o), InputError);  // several pressing times, none chosen
  o.pressing_time = 50;
  try {
    MeasuredCreaseLaw law(d, o, "scene.yaml", "sheet.folds[0].law");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "scene.yaml");
    EXPECT_EQ(e.field(), "sheet.folds[0].law.pressing_time");
    EXPECT_NE(std::string(e.what()).find("10, 40"), std::string::npos) << e.what();
  }
}

TEST(CreaseLaw, RelaxationShiftsRestAngleLogarithmically) {
  const double c = 3 * kDegToRad, tau = 60, age = 600, age_ref = 600;
  auto base = std::make_shared<LinearCreaseLaw>(0.01, 150 * kDegToRad);
  const RelaxingCreaseLaw law(base, c, tau, age, age_ref);
  const ElementHistory h;
  EXPECT_NEAR(law.rest_angle(h, 0), 150 * kDegToRad, 1e-15);
  for (double t : {1.0, 100.0, 1e4, 1e6}) {
    const double delta = c * std::log((1 + (age + t) / tau) / (1 + age_ref / tau));
    EXPECT_NEAR(law.rest_angle(h, t), 150 * kDegToRad - delta, 1e-13);
    const double phi = 140 * kDegToRad;
    EXPECT_NEAR(law.evaluate(phi, h, t).moment, 0.01 * (phi + delta - 150 * kDegToRad), 1e-15);
    EXPECT_NEAR(law.evaluate(phi, h, t).moment, fd_energy(law, phi, h, t), 1e-9);
  }
  // A linear law in the signed angle folded the negative way relaxes towards flat too.
  const RelaxingCreaseLaw neg(std::make_shared<LinearCreaseLaw>(0.01, -150 * kDegToRad), c, tau,
                              age, age_ref);
  const double d1 = c * std::log((1 + (age + 100) / tau) / (1 + age_ref / tau));
  EXPECT_NEAR(neg.rest_angle(h, 100), -150 * kDegToRad + d1, 1e-13);
  EXPECT_FALSE(neg.direction_relative());
  EXPECT_THROW(RelaxingCreaseLaw bad(base, c, 0, age, age_ref), InputError);
  EXPECT_THROW(RelaxingCreaseLaw bad(base, c, tau, -1, age_ref), InputError);
}

}  // namespace crease_law_test
