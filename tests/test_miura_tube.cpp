// The Miura tube (issue 13 item 5, docs/fold.md "The Miura tube"): a two-row Miura strip and
// its mirror image about z = 0, seamed along their ridge lines and closed by rhombic caps.
// Its folded coordinates against its development (an exact isometry of planar faces at any
// fold angle), its section against the closed form (a rhombus of side a with L V = a b cos
// gamma), its volume against 2 L H x columns S to round-off, the largest volume
// columns b a^2 sin^2(gamma) at 45 deg, and bad specs refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"
#include "elements/chamber_gas.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "patterns/miura_tube_pattern.hpp"
#include "patterns/pattern_checks.hpp"
#include "pressure_test_util.hpp"

namespace finseg {
namespace miura_tube_test {

MiuraTubeSpec tube(double theta_deg, int columns = 5) {
  MiuraTubeSpec s;
  s.columns = columns;
  s.side_a = 0.02;
  s.side_b = 0.026;
  s.sector_angle = 55 * kDegToRad;
  s.fold_angle = theta_deg * kDegToRad;
  return s;
}

// Every edge and both diagonals of every face as long folded as flat, every quadrilateral
// planar, every seam's joined ends coincident, at fold angles across the range.
TEST(MiuraTube, FoldedCoordinatesAreAnIsometryOfPlanarFaces) {
  for (const double deg : {5.0, 30.0, 45.0, 70.0, 85.0, 89.0}) {
    CreasePattern p = miura_tube_crease_pattern(tube(deg));
    validate_pattern(p, "<miura tube>");
    const MiuraTubeSpec s = tube(deg);
    ASSERT_EQ(p.faces.size(), static_cast<std::size_t>(4 * s.columns + 2));
    double worst = 0, worst_planar = 0, worst_seam = 0;
    for (const auto& f : p.faces) {
      for (std::size_t u = 0; u < f.size(); ++u) {
        for (std::size_t v = u + 1; v < f.size(); ++v) {
          const double flat = (p.vertices_flat_m[f[u]] - p.vertices_flat_m[f[v]]).norm();
          const double folded = (p.vertices_folded_m[f[u]] - p.vertices_folded_m[f[v]]).norm();
          worst = std::max(worst, std::abs(folded - flat) / s.side_b);
        }
      }
      const Vec3 &a = p.vertices_folded_m[f[0]], &b = p.vertices_folded_m[f[1]],
                 &c = p.vertices_folded_m[f[2]], &d = p.vertices_folded_m[f[3]];
      const Vec3 normal = (b - a).cross(c - a).normalized();
      worst_planar = std::max(worst_planar, std::abs(normal.dot(d - a)) / s.side_b);
    }
    for (const auto& seam : p.seams) {
      const PatternEdge &a = p.edges[seam[0]], &b = p.edges[seam[1]];
      worst_seam = std::max(
          {worst_seam,
           (p.vertices_folded_m[a.vertices[0]] - p.vertices_folded_m[b.vertices[1]]).norm(),
           (p.vertices_folded_m[a.vertices[1]] - p.vertices_folded_m[b.vertices[0]]).norm()});
    }
    EXPECT_LT(worst, 1e-14) << deg;
    EXPECT_LT(worst_planar, 1e-14) << deg;
    EXPECT_EQ(worst_seam, 0.0) << deg;  // the same coordinates, mirrored: exactly equal
    // Two ridge lines of `columns` seams, four per cap.
    EXPECT_EQ(p.seams.size(), static_cast<std::size_t>(2 * s.columns + 8));
    // Seamed and capped, a sphere: V - E + F = 2 with every seam's two edges one edge and
    // the points they join one vertex.
    std::map<std::array<long, 3>, int> unique;
    for (const Vec3& x : p.vertices_folded_m) {
      unique[{std::lround(x.x() * 1e10), std::lround(x.y() * 1e10), std::lround(x.z() * 1e10)}] = 1;
    }
    const int v = static_cast<int>(unique.size());
    const int e = static_cast<int>(p.edges.size() - p.seams.size());
    EXPECT_EQ(v - e + static_cast<int>(p.faces.size()), 2) << deg;
  }
}

// The section's closed form: a rhombus of side a (L^2 + H^2 = a^2), half-width L and the
// zigzag's sideways step V with L V = a b cos(gamma) (the sector angle kept), read from the
// folded vertices of the middle column; flat (L = a, H = 0) and full fold (L = a cos gamma,
// length 0) at the ends of the range.
TEST(MiuraTube, SectionIsARhombusOfTheClosedForm) {
  const MiuraTubeSpec s = tube(60);
  const double a = s.side_a, b = s.side_b, g = s.sector_angle;
  for (const double deg : {1.0, 20.0, 45.0, 60.0, 80.0, 89.9}) {
    const double th = deg * kDegToRad;
    const MiuraTubeShape t = miura_tube_shape(s, th);
    EXPECT_NEAR(t.half_width * t.half_width + t.half_height * t.half_height, a * a, 1e-15);
    const Vec3 r1 = miura_tube_vertex(s, th, 0, 0, 3), top = miura_tube_vertex(s, th, 0, 1, 3);
    const Vec3 r2 = miura_tube_vertex(s, th, 0, 2, 3), bot = miura_tube_vertex(s, th, 1, 1, 3);
    EXPECT_NEAR((r2 - r1).norm(), 2 * t.half_width, 1e-15);
    EXPECT_NEAR((top - bot).norm(), 2 * t.half_height, 1e-15);
    // The zigzag side b = (S, V, 0) between columns: the angle between it and the section's
    // side (0, L, H) is gamma.
    const Vec3 along = miura_tube_vertex(s, th, 0, 0, 4) - r1;
    EXPECT_NEAR(along.norm(), b, 1e-15);
    EXPECT_NEAR(std::abs(along.dot(top - r1)), a * b * std::cos(g), 1e-15);
    EXPECT_NEAR(std::abs(along.y()) * t.half_width, a * b * std::cos(g), 1e-15);
  }
  EXPECT_NEAR(miura_tube_shape(s, 0).half_width, a, 1e-15);
  EXPECT_NEAR(miura_tube_shape(s, kPi / 2).half_width, a * std::cos(g), 1e-15);
  EXPECT_NEAR(miura_tube_shape(s, kPi / 2).length, 0, 1e-15);
}

// The volume's closed form and its largest value: V(theta) = 2 L H columns S is largest at
// 45 deg for every sector angle, columns b a^2 sin^2(gamma) (derived in docs/fold.md), and
// falls to 0 flat and fully folded.
TEST(MiuraTube, VolumeIsLargestAt45DegreesForEverySectorAngle) {
  for (const double gamma_deg : {20.0, 55.0, 80.0}) {
    MiuraTubeSpec s = tube(60);
    s.sector_angle = gamma_deg * kDegToRad;
    const double vmax = miura_tube_max_volume(s);
    EXPECT_NEAR(miura_tube_volume(s, kPi / 4) / vmax, 1, 1e-14) << gamma_deg;
    for (double deg = 0.5; deg < 90; deg += 0.5) {
      EXPECT_LE(miura_tube_volume(s, deg * kDegToRad), vmax * (1 + 1e-14)) << deg;
    }
    EXPECT_NEAR(miura_tube_volume(s, 0), 0, 1e-18);
    EXPECT_NEAR(miura_tube_volume(s, kPi / 2), 0, 1e-18);
  }
}

Model tube_model(const CreasePattern& p, int subdivisions) {
  PatternSheetSpec spec;
  spec.thickness = 1e-4;
  spec.youngs_modulus = 3e9;
  spec.poisson_ratio = 0.3;
  spec.density = 1000;
  spec.subdivisions = subdivisions;
  spec.mountain_law = std::make_shared<LinearCreaseLaw>(0.01, 0.0);
  spec.valley_law = std::make_shared<LinearCreaseLaw>(0.01, 0.0);
  spec.laws_rest_at_pattern = true;
  return build_pattern_model(p, spec, "<miura tube>");
}

// The capped tube is one closed chamber of the closed-form volume to round-off, stowed and
// part deployed, at any subdivision; without a cap (or with one face left out) it is open and
// refused.
TEST(MiuraTube, CappedTubeIsAClosedChamberOfTheClosedFormVolume) {
  for (const double deg : {80.0, 45.0, 20.0}) {
    const MiuraTubeSpec s = tube(deg);
    const CreasePattern p = miura_tube_crease_pattern(s);
    for (int n : {1, 2}) {
      Model m = tube_model(p, n);
      m.chambers.push_back(test::whole_model_chamber(m, "tube"));
      prepare_chambers(m);
      EXPECT_NEAR(m.chambers[0].initial_volume / miura_tube_volume(s, s.fold_angle), 1, 1e-12)
          << deg << " deg, subdivisions " << n;
    }
  }
  MiuraTubeSpec open = tube(80);
  open.caps = false;
  Model m = tube_model(miura_tube_crease_pattern(open), 1);
  m.chambers.push_back(test::whole_model_chamber(m, "tube"));
  EXPECT_THROW(prepare_chambers(m), InputError);
}

// Soft seams (PatternSheetSpec::soft_seams): the joints across the listed seams have their
// in-plane springs (T1, T2, theta3) scaled, the others kept; no other joint's out-of-plane
// springs change; bad lists refused naming the field.
TEST(MiuraTube, SoftSeamsScaleTheInPlaneSpringsOfTheirJointsOnly) {
  const MiuraTubeSpec s = tube(80, 3);
  const CreasePattern p = miura_tube_crease_pattern(s);
  const Model stiff = tube_model(p, 1);
  PatternSheetSpec spec;
  spec.thickness = 1e-4;
  spec.youngs_modulus = 3e9;
  spec.poisson_ratio = 0.3;
  spec.density = 1000;
  spec.mountain_law = spec.valley_law = std::make_shared<LinearCreaseLaw>(0.01, 0.0);
  spec.laws_rest_at_pattern = true;
  const int first_cap_seam = 2 * s.columns;  // after the two ridge lines
  spec.soft_seams = {{{first_cap_seam, first_cap_seam + 5}, 1e-3}};
  const Model soft = build_pattern_model(p, spec, "<miura tube>");
  ASSERT_EQ(soft.elements.size(), stiff.elements.size());
  int scaled = 0;
  for (std::size_t k = 0; k < soft.elements.size(); ++k) {
    const std::string& name = soft.elements[k].name;
    const bool listed = name.rfind(fmt::format("seam{}_", first_cap_seam + 1), 0) == 0 ||
                        name.rfind(fmt::format("seam{}_", first_cap_seam + 6), 0) == 0;
    // Out of plane (T3, twist, bending) untouched; the in-plane turn scaled exactly. Stretch
    // and shear are scaled too, but the cells beside a soft side no longer count it when their
    // joints are limited to plane stress (limit_joints_to_plane_stress), so there the ratio
    // is the scale over that limit (within 1.5 on these parallelograms).
    for (int i : {2, 3, 4}) {
      EXPECT_NEAR(soft.elements[k].K[i] / stiff.elements[k].K[i], 1.0, 1e-12) << name << " " << i;
    }
    EXPECT_NEAR(soft.elements[k].K[5] / stiff.elements[k].K[5], listed ? 1e-3 : 1.0, 1e-12) << name;
    for (int i : {0, 1}) {
      const double ratio = soft.elements[k].K[i] / stiff.elements[k].K[i];
      EXPECT_GE(ratio, listed ? 1e-3 * (1 - 1e-12) : 1 / 1.5) << name << " " << i;
      EXPECT_LE(ratio, listed ? 1.5e-3 : 1.5) << name << " " << i;
    }
    scaled += listed;
  }
  EXPECT_EQ(scaled, 2);  // one cell side per seam at one segment per face
  auto refused = [&](std::vector<SoftSeams> lists, const std::string& field) {
    PatternSheetSpec bad = spec;
    bad.soft_seams = std::move(lists);
    try {
      build_pattern_model(p, bad, "<miura tube>");
      ADD_FAILURE() << field << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  };
  refused({{{0}, 0.0}}, "soft_seams[0].scale");
  refused({{{0}, 1.5}}, "soft_seams[0].scale");
  refused({{{0}, 0.5}, {{static_cast<int>(p.seams.size())}, 0.5}}, "soft_seams[1].seams");
  refused({{{3, 3}, 0.5}}, "soft_seams[0].seams");
}

TEST(MiuraTube, RefusesSpecsOutOfRange) {
  auto refused = [](auto change, const char* field) {
    MiuraTubeSpec s = tube(80);
    change(s);
    try {
      miura_tube_crease_pattern(s);
      ADD_FAILURE() << field << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  };
  refused([](MiuraTubeSpec& s) { s.columns = 0; }, "columns");
  refused([](MiuraTubeSpec& s) { s.columns = 1001; }, "columns");
  refused([](MiuraTubeSpec& s) { s.side_a = 0; }, "side_a");
  refused([](MiuraTubeSpec& s) { s.side_b = std::nan(""); }, "side_b");
  refused([](MiuraTubeSpec& s) { s.sector_angle = kPi / 2; }, "sector_angle");
  refused([](MiuraTubeSpec& s) { s.sector_angle = 0; }, "sector_angle");
  refused([](MiuraTubeSpec& s) { s.fold_angle = 0; }, "fold_angle");  // flat: no volume
  refused([](MiuraTubeSpec& s) { s.fold_angle = kPi / 2; }, "fold_angle");
  MiuraTubeSpec s = tube(80);
  s.caps = false;
  EXPECT_THROW(miura_tube_cap_face(s, 1), InputError);
  EXPECT_THROW(miura_tube_column_faces(s, s.columns), InputError);
}

}  // namespace miura_tube_test
}  // namespace finseg
