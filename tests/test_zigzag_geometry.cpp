// The generated zigzag matches its closed-form geometry.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "generators/zigzag.hpp"

namespace finseg {
namespace zigzag_geometry_test {

TEST(ZigzagGeometry, PanelsCreasesAndAnglesAreExact) {
  ZigzagSpec spec;  // the paper's strip: 480 x 40 mm, 6 panels, 80 deg
  const Model m = build_zigzag_model(spec);
  const double Lp = 0.08, th = 80 * kPi / 180;
  // Extent of a body along the strip on the flat sheet, m.
  const auto s_range = [](const BodyDef& b) {
    double lo = 1e9, hi = -1e9;
    for (const Vec2& v : material_outline(b)) lo = std::min(lo, v.x()), hi = std::max(hi, v.x());
    return std::pair(lo, hi);
  };
  double total = 0;
  for (const BodyDef& b : m.bodies) total += s_range(b).second - s_range(b).first;
  EXPECT_NEAR(total, 0.48, 1e-12);
  for (const BodyDef& b : m.bodies) {
    const auto [s_min, s_max] = s_range(b);
    // Every body lies inside one panel and carries that panel's elevation.
    const int panel = static_cast<int>(std::floor(0.5 * (s_min + s_max) / Lp));
    EXPECT_EQ(b.panel, panel);
    EXPECT_LE(s_max, (panel + 1) * Lp + 1e-12);
    EXPECT_GE(s_min, panel * Lp - 1e-12);
    const Vec3 dir = b.R0_WB.col(0);
    const double elevation = std::asin(dir.z());
    EXPECT_NEAR(elevation, panel % 2 == 0 ? th : -th, 1e-12);
    EXPECT_NEAR(dir.y(), 0, 1e-15);
    // Material point at the body's start edge lies on the closed-form zigzag.
    const Vec3 start = b.p0_W + b.R0_WB * Vec3(-0.5 * (s_max - s_min), 0, 0);
    const double along = s_min - panel * Lp;
    const double x0 = panel * Lp * std::cos(th), z0 = panel % 2 == 0 ? 0 : Lp * std::sin(th);
    EXPECT_NEAR(start.x(), x0 + along * std::cos(th), 1e-12);
    EXPECT_NEAR(start.z(), z0 + (panel % 2 == 0 ? 1 : -1) * along * std::sin(th), 1e-12);
    EXPECT_EQ(b.fixed, panel == 0 || panel == 5);
  }
  // Creases: five, at s = k Lp, alternating +-2 theta starting with a peak.
  ASSERT_EQ(m.creases.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(m.creases[k].initial_fold_angle, (k % 2 == 0 ? 2 : -2) * th, 1e-15);
  }
  // The gauge pulls the middle crease, a peak at height Lp sin(theta), straight up.
  ASSERT_EQ(m.drives.size(), 1u);
  EXPECT_NEAR(m.drives[0].start_W.x(), 3 * Lp * std::cos(th), 1e-12);
  EXPECT_NEAR(m.drives[0].start_W.z(), Lp * std::sin(th), 1e-12);
  EXPECT_NEAR(m.drives[0].travel, 0.9 * 2 * Lp * std::sin(th), 1e-12);
}

TEST(ZigzagGeometry, RejectsImpossibleInput) {
  ZigzagSpec s;
  s.fold_angle = 95 * kPi / 180;
  EXPECT_THROW(build_zigzag_model(s), InputError);
  s = ZigzagSpec{};
  s.fixed_panels = {1, 2, 3, 4, 5, 6};
  EXPECT_THROW(build_zigzag_model(s), InputError);
  s = ZigzagSpec{};
  s.pulled_crease = 6;
  EXPECT_THROW(build_zigzag_model(s), InputError);
  s = ZigzagSpec{};
  s.pattern = "PVPX";
  EXPECT_THROW(build_zigzag_model(s), InputError);
}

}  // namespace zigzag_geometry_test
}  // namespace finseg
