// The zigzag strip's FOLD crease pattern against the strip's closed-form geometry, and the
// `finseg pattern` commands.
#include <cmath>

#include "pattern_test_util.hpp"
#include "patterns/pattern_checks.hpp"
#include "patterns/zigzag_pattern.hpp"

namespace finseg::test {
namespace fold_zigzag_test {

TEST(FoldZigzag, CountsAnglesAndFoldedGeometry) {
  ZigzagSpec z;  // paper strip: 6 panels of 80 mm x 40 mm, panels at 80 deg, PVPVP
  CreasePattern p = zigzag_crease_pattern(z);
  const int n = z.panels;
  EXPECT_EQ(p.vertices_flat_m.size(), static_cast<std::size_t>(2 * (n + 1)));
  EXPECT_EQ(p.faces.size(), static_cast<std::size_t>(n));
  EXPECT_EQ(p.edges.size(), static_cast<std::size_t>(3 * n + 1));
  EXPECT_NO_THROW(validate_pattern(p, "<zigzag>"));
  const double a = z.fold_angle, lp = z.length / n;
  int creases = 0;
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    const PatternEdge& edge = p.edges[e];
    if (!is_crease(edge.assignment)) continue;
    // Crease k (1-based) at x = k lp; odd k are peaks: mountains, folded by 180 - 2 (90 - a).
    const int k = static_cast<int>(std::lround(p.vertices_flat_m[edge.vertices[0]].x() / lp));
    const bool peak = k % 2 == 1;
    EXPECT_EQ(edge.assignment, peak ? EdgeAssignment::Mountain : EdgeAssignment::Valley) << k;
    EXPECT_NEAR(edge.fold_angle, (peak ? -1 : 1) * 2 * a, 1e-14) << k;
    // The same angle measured on the folded coordinates' face normals.
    EXPECT_NEAR(measured_fold_angle(p, static_cast<int>(e)), edge.fold_angle, 1e-12) << k;
    ++creases;
  }
  EXPECT_EQ(creases, n - 1);
  // Folded: crease line k at x = k lp cos a, z = lp sin a at peaks and 0 at valleys.
  for (int k = 0; k <= n; ++k) {
    for (int side = 0; side < 2; ++side) {
      const Vec3 expected(k * lp * std::cos(a), side * z.width, k % 2 ? lp * std::sin(a) : 0);
      EXPECT_LT((p.vertices_folded_m[2 * k + side] - expected).norm(), 1e-15) << k;
    }
  }
}

TEST(FoldZigzag, CliWritesChecksAndRefuses) {
  TempDir dir;
  CliResult r = run_finseg(dir, "pattern zigzag --panels 4 --fold-angle 60 --out z.fold");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "pattern check z.fold");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("10 vertices, 4 faces, 13 edges (10 B, 2 M, 1 V)"), std::string::npos)
      << r.out;
  r = run_finseg(dir, "pattern info z.fold");
  EXPECT_NE(r.out.find("fold angles -120 .. 120 deg"), std::string::npos) << r.out;
  r = run_finseg(dir, "pattern zigzag --panels 4 --pattern PPVV");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("<cli>: pattern: needs 3 letters"), std::string::npos) << r.err;

  nlohmann::json unitless = two_squares();
  unitless.erase("frame_unit");
  spit(dir / "u.fold", unitless.dump());
  r = run_finseg(dir, "pattern check u.fold");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("u.fold: frame_unit: absent"), std::string::npos) << r.err;
  r = run_finseg(dir, "pattern info u.fold --unit cm");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("flat extent 0.02 x 0.01 m"), std::string::npos) << r.out;
}

}  // namespace fold_zigzag_test
}  // namespace finseg::test
