// The gathered cone (`cone_gathered`, `finseg gen cone --gathered F`) as a start state with
// contact on: no pair of segments that the contact rules let touch starts closer than the sum
// of their half thicknesses (the exact distance between their mid-surface polygons, not the
// contact's samples), so no contact force acts at the start; the fan stack, whose facets
// coincide, fails the same check (the reason it cannot start with contact on); and the
// shipped examples/cone/gathered.yaml and inflate.yaml are such starts, with the contact
// stiffness of the generator's rule (docs/folding.md, "Contact of the generated scenes"); pulled
// with contact on, the layers that meet stay apart to within the quarter thickness.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <tuple>
#include <vector>

#include "cli_test_util.hpp"
#include "collision/contact_forces.hpp"
#include "collision/pair_rules.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "model/state.hpp"
#include "patterns/cone_pattern.hpp"
#include "patterns/pattern_checks.hpp"
#include "scene/scene_reader.hpp"
#include "test_paths.hpp"

namespace finseg {
namespace cone_gathered_test {

using Polygon = std::vector<Vec3>;

double segment_distance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  // Closest points of two segments (Ericson, Real-Time Collision Detection 5.1.9).
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r), c = d1.dot(r),
               b = d1.dot(d2), den = a * e - b * b;
  double s = den > 1e-30 * a * e ? std::clamp((b * f - c * e) / den, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0) t = 0, s = std::clamp(-c / a, 0.0, 1.0);
  if (t > 1) t = 1, s = std::clamp((b - c) / a, 0.0, 1.0);
  return (p0 + s * d1 - (q0 + t * d2)).norm();
}

Vec3 normal_of(const Polygon& P) {
  Vec3 n = Vec3::Zero();
  for (std::size_t i = 0; i < P.size(); ++i) n += P[i].cross(P[(i + 1) % P.size()]);
  return n.normalized();
}

// Does x (in P's plane) lie inside convex polygon P (counter-clockwise about n)?
bool inside(const Polygon& P, const Vec3& n, const Vec3& x) {
  for (std::size_t i = 0; i < P.size(); ++i) {
    if ((P[(i + 1) % P.size()] - P[i]).cross(x - P[i]).dot(n) < 0) return false;
  }
  return true;
}

double point_polygon_distance(const Polygon& P, const Vec3& x) {
  const Vec3 n = normal_of(P);
  const double h = n.dot(x - P[0]);
  if (inside(P, n, x - h * n)) return std::abs(h);
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < P.size(); ++i) {
    d = std::min(d, segment_distance(x, x, P[i], P[(i + 1) % P.size()]));
  }
  return d;
}

// An edge of A passing through the inside of B.
bool pierces(const Polygon& A, const Polygon& B) {
  const Vec3 n = normal_of(B);
  for (std::size_t i = 0; i < A.size(); ++i) {
    const Vec3 &p = A[i], &q = A[(i + 1) % A.size()];
    const double hp = n.dot(p - B[0]), hq = n.dot(q - B[0]);
    if (hp * hq >= 0) continue;
    if (inside(B, n, p + hp / (hp - hq) * (q - p))) return true;
  }
  return false;
}

// Exact distance between two convex polygons in 3-D: 0 when they cross, else the least of
// the vertex-to-polygon and edge-to-edge distances.
double polygon_distance(const Polygon& A, const Polygon& B) {
  if (pierces(A, B) || pierces(B, A)) return 0;
  double d = std::numeric_limits<double>::infinity();
  for (const Vec3& a : A) d = std::min(d, point_polygon_distance(B, a));
  for (const Vec3& b : B) d = std::min(d, point_polygon_distance(A, b));
  for (std::size_t i = 0; i < A.size(); ++i) {
    for (std::size_t j = 0; j < B.size(); ++j) {
      d = std::min(d, segment_distance(A[i], A[(i + 1) % A.size()], B[j], B[(j + 1) % B.size()]));
    }
  }
  return d;
}

// Least signed gap (mid-surface distance less the half thicknesses) over every pair of
// segments the contact rules let touch, at the model's start poses; and how many pairs.
struct GapResult {
  double gap = std::numeric_limits<double>::infinity();
  int pairs = 0;
};

GapResult least_gap(const Model& m) {
  std::vector<Polygon> world(m.bodies.size());
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    const BodyDef& b = m.bodies[i];
    for (const Vec2& c : b.outline_B) world[i].push_back(b.p0_W + b.R0_WB * Vec3(c.x(), c.y(), 0));
  }
  const PairRules rules(m);
  GapResult r;
  for (std::size_t a = 0; a < world.size(); ++a) {
    for (std::size_t b = a + 1; b < world.size(); ++b) {
      if (!rules.may_touch(static_cast<int>(a), static_cast<int>(b))) continue;
      ++r.pairs;
      const double half = 0.5 * (m.bodies[a].thickness + m.bodies[b].thickness);
      r.gap = std::min(r.gap, polygon_distance(world[a], world[b]) - half);
    }
  }
  return r;
}

// The cone of examples/cone: 6 pleats, 2 axial folds, open ends.
ConeSpec lab_cone() {
  ConeSpec s;
  s.pleats = 6;
  s.axial_folds = 2;
  s.top_disc = s.base_disc = false;
  return s;
}

// That cone on 0.1 mm paper with contact on, started from `folded` (vertices of the
// pattern), each face cut n x n.
Model cone_model(const std::vector<Vec3>& folded, int n, const ConeSpec& s = lab_cone()) {
  CreasePattern p = cone_crease_pattern(s);
  p.vertices_folded_m = folded;
  validate_pattern(p, "<cone>");
  PatternSheetSpec spec;
  spec.thickness = 1e-4;
  spec.subdivisions = n;
  spec.mountain_law = std::make_shared<LinearCreaseLaw>(0.05, 0.0);
  spec.valley_law = std::make_shared<LinearCreaseLaw>(0.05, 0.0);
  Model m = build_pattern_model(p, spec, "<cone>");
  m.contact.enabled = true;
  m.contact.stiffness = 8e6;
  return m;
}

// A shipped example scene `m`: contact on, no pair closer than the thickness, no contact
// point at the start, and the generator's contact: one face carrying the reference force sinks
// a quarter of the thickness, F = K (t/4)^1.5, and its anchor friction's spring carries
// mu_s F at a quarter of the thickness of slip (docs/folding.md, "Contact of the generated
// scenes").
void expect_example_start(const Model& m, double force) {
  ASSERT_TRUE(m.contact.enabled);
  EXPECT_GE(least_gap(m).gap, 0);
  EXPECT_EQ(contact_summary(m, initial_state(m)).active, 0);
  const double t = m.bodies.front().thickness;
  EXPECT_NEAR(m.contact.stiffness * std::pow(0.25 * t, 1.5), force, 1e-3 * force);
  EXPECT_EQ(m.contact.friction, FrictionModel::Anchor);
  EXPECT_NEAR(m.contact.tangential_stiffness * 0.25 * t, m.contact.mu_static * force,
              1e-3 * m.contact.mu_static * force);
}

TEST(ConeGathered, NoPairStartsInContact) {
  const ConeSpec s = lab_cone();
  const CreasePattern p = cone_crease_pattern(s);
  for (const double gather : {0.5, 0.8, 0.9}) {
    for (const int n : {1, 2}) {
      const Model m = cone_model(cone_gathered(s, p, gather), n);
      const GapResult g = least_gap(m);
      EXPECT_GT(g.pairs, 0);
      EXPECT_GE(g.gap, 0) << "gather " << gather << ", " << n << " x " << n << " cells";
      std::printf("gather %g, %d x %d cells: %zu segments, %d pairs, least gap %.4g mm\n", gather,
                  n, n, m.bodies.size(), g.pairs, 1e3 * g.gap);
      // The contact's own detection agrees: no sample point touches.
      EXPECT_EQ(contact_summary(m, initial_state(m)).active, 0);
    }
  }
}

// The wall stowed by reflection (`cone_reflected`): its bands lie nested, at the rings' fold
// angles, not on one another, so it too starts with contact on and nothing touching; the lab
// cone (12 pleats, 6 folds) included.
TEST(ConeGathered, TheWallStowedByReflectionStartsApart) {
  for (const int pleats : {6, 12}) {
    for (const double gather : {0.5, 0.8}) {
      for (const int n : {1, 2}) {
        ConeSpec s = lab_cone();
        s.pleats = pleats;
        s.axial_folds = pleats == 12 ? 6 : 2;
        s.reflect_gather = gather;
        const Model m = cone_model(cone_reflected(s, cone_crease_pattern(s)), n, s);
        const GapResult g = least_gap(m);
        EXPECT_GT(g.pairs, 0);
        EXPECT_GE(g.gap, 0) << pleats << " pleats, gather " << gather << ", " << n << " x " << n;
        std::printf(
            "reflected, %d pleats, gather %g, %d x %d cells: %zu segments, %d pairs, "
            "least gap %.4g mm\n",
            pleats, gather, n, n, m.bodies.size(), g.pairs, 1e3 * g.gap);
        EXPECT_EQ(contact_summary(m, initial_state(m)).active, 0);
      }
    }
  }
  // The shipped examples: apart, with the generator's contact stiffness for its pull, a drive
  // on each end band's whole facet (2 (2 pleats - 1)): F = one gauge's largest pull (stiffness
  // x travel, the first drive a top one); pulled, the apex drawn up and the base pinned;
  // inflated, both ends drawn apart by strings (free across the axis, slack when pushed, a toe
  // of 3 % of F) round the chamber of the wall. lab_pull.yaml and lab_inflate.yaml are the
  // issue's cone (12 pleats, 6 axial folds).
  const std::tuple<const char*, std::size_t, bool> examples[] = {
      {"reflected.yaml", 22, false},
      {"lab_pull.yaml", 46, false},
      {"reflected_inflate.yaml", 22, true},
      {"lab_inflate.yaml", 46, true}};
  for (const auto& [file, drives, inflated] : examples) {
    SCOPED_TRACE(file);
    const Scene scene = read_scene(std::string(FINSEG_SOURCE_DIR) + "/examples/cone/" + file);
    ASSERT_EQ(scene.model.drives.size(), drives);
    const DriveDef& gauge = scene.model.drives[0];
    expect_example_start(scene.model, gauge.stiffness * gauge.travel);
    for (std::size_t k = 1; k < drives; k += 2) {  // top, base, top, base, ...
      EXPECT_EQ(scene.model.drives[k].travel, inflated ? gauge.travel : 0.0);
    }
    EXPECT_EQ(scene.model.chambers.size(), inflated ? 1u : 0u);
    // The pulls measure their error at the facets' points; the inflations, whose first contact
    // grazes, in m and rad (docs/solvers.md, "The error at a segment's points").
    EXPECT_EQ(scene.solver.error_at_points, !inflated);
    for (const DriveDef& d : scene.model.drives) {
      EXPECT_EQ(d.lateral_ratio, inflated ? 0 : 1);
      EXPECT_EQ(d.pull_only, inflated);
      EXPECT_NEAR(d.toe_force, inflated ? 0.03 * d.stiffness * d.travel : 0.0, 1e-3 * d.toe_force);
    }
  }
}

TEST(ConeGathered, TheFanStacksFacetsCoincide) {
  const ConeSpec s = lab_cone();
  const CreasePattern p = cone_crease_pattern(s);
  const Model m = cone_model(cone_fan_stack(s, p, 150 * kDegToRad), 1);
  const GapResult g = least_gap(m);
  // Stacked facets lie on one another: a whole thickness into each other.
  EXPECT_NEAR(g.gap, -1e-4, 1e-9);
  EXPECT_GT(contact_summary(m, initial_state(m)).active, 0);
}

TEST(ConeGathered, ExampleScenesStartApartWithTheRulesContactStiffness) {
  for (const char* file : {"gathered.yaml", "inflate.yaml"}) {
    SCOPED_TRACE(file);
    const Scene scene = read_scene(std::string(FINSEG_SOURCE_DIR) + "/examples/cone/" + file);
    const Scene pull = read_scene(std::string(FINSEG_SOURCE_DIR) + "/examples/cone/gathered.yaml");
    // F: the largest pull (stiffness x travel) of the pull scene's one gauge.
    ASSERT_EQ(pull.model.drives.size(), 1u);
    expect_example_start(scene.model, pull.model.drives[0].stiffness * pull.model.drives[0].travel);
  }
  // The inflation's chamber closes (read_scene refuses an open one) round the whole wall.
  const Scene gas = read_scene(std::string(FINSEG_SOURCE_DIR) + "/examples/cone/inflate.yaml");
  ASSERT_EQ(gas.model.chambers.size(), 1u);
  EXPECT_TRUE(gas.model.drives.empty());
}

TEST(ConeGathered, ExamplePullRunsWithContactOnAndPenetrationBelowAQuarterThickness) {
  // examples/cone/gathered.yaml as shipped (1 s of implicit pull; 3.6 s wall in Release).
  test::TempDir dir;
  const auto r = test::run_example(dir, "cone", "gathered.yaml", {"gathered.fold"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::string header;
  const auto rows = test::csv_rows(test::slurp(dir / "run/contact.csv"), &header);
  ASSERT_EQ(header, test::kContactProbeHeader);
  ASSERT_GT(rows.size(), 50u);
  EXPECT_NEAR(rows.back()[0], 1.0, 1e-9);  // the whole pull
  int touching = 0;
  double deepest = 0;
  for (const auto& row : rows) {
    touching = std::max(touching, static_cast<int>(row[1]));
    deepest = std::max(deepest, row[4]);
  }
  EXPECT_EQ(rows.front()[1], 0);  // apart at the start
  EXPECT_GT(touching, 0);         // the pull brings layers together
  EXPECT_LT(deepest, 0.25e-4);    // t / 4, t = 0.1 mm
}

}  // namespace cone_gathered_test
}  // namespace finseg
