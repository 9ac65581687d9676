// Cantilever under a dead end moment: the exact solution is a circular arc of curvature
// M / (E I) (tests/elastica_reference.hpp: arc_tip).
#include <gtest/gtest.h>

#include <numbers>

#include "elastica_reference.hpp"
#include "validation_cantilever.hpp"

namespace finseg {
namespace validation_end_moment_test {

using std::numbers::pi;

// Tip displacement under the end moment M = c E I / L about -y (curls the strip up, +z).
Vec3 tip_under_end_moment(double c, int segments) {
  CantileverSpec s = validation::slender_strip(segments);
  s.tip_moment = Vec3(0, -c * bending_rigidity(s) / s.length, 0);
  return validation::static_tip_displacement(s);
}

// The static solver needs thousands of Newton iterations to roll the slender strip up (the
// stiff stretching springs keep its steps short), so 16 segments keep the test quick; the
// closure does not depend on the resolution (the chain is closed up to the solver tolerance).
TEST(EndMoment, FullCircleBringsTipBackToClamp) {
  const CantileverSpec s = validation::slender_strip(16);
  const Vec3 d = tip_under_end_moment(2 * pi, 16);
  // Tip position relative to the clamped end of the strip, (0, w/2, 0).
  const Vec3 tip = d + Vec3(s.length, 0, 0);
  std::printf("full circle: tip at (%.3e, %.3e, %.3e) m from the clamp\n", tip.x(), tip.y(),
              tip.z());
  EXPECT_LT(tip.norm(), 5e-3 * s.length);
}

TEST(EndMoment, QuarterArcMatchesClosedForm) {
  const CantileverSpec s = validation::slender_strip(32);
  const reference::ArcTip ref = reference::arc_tip(pi / 2);
  const Vec3 d = tip_under_end_moment(pi / 2, 32);
  const double along = 1 + d.x() / s.length, up = d.z() / s.length;
  std::printf("quarter arc: tip (%.6f, %.6f) L, closed form (%.6f, %.6f) L\n", along, up, ref.along,
              ref.across);
  EXPECT_NEAR(along / ref.along, 1.0, 5e-3);
  EXPECT_NEAR(up / ref.across, 1.0, 5e-3);
  EXPECT_NEAR(d.y(), 0.0, 1e-9 * s.length);
}

}  // namespace validation_end_moment_test
}  // namespace finseg
