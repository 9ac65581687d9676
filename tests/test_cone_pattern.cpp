// The generated cone (src/patterns/cone_pattern.*) against the faceted cone's closed form:
// the development is an isometry of the truncated pyramid through the base and top polygons'
// corners, the seam closes, every interior ring vertex is flat-foldable (Kawasaki: alternate
// sector angles sum to pi; Maekawa: mountains and valleys differ by 2), the open-end
// options leave the discs out, the fan stack (every generator at 180 degrees, the rings
// Z-folded) is an isometry with the rings folded by the asked angle of their kinds, and the
// gathered wall is an isometry with flat rings and its generators folded towards their kinds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "core/error.hpp"
#include "patterns/cone_pattern.hpp"
#include "patterns/pattern_checks.hpp"

namespace finseg {
namespace cone_pattern_test {

ConeSpec open_cone() {
  ConeSpec s;
  s.pleats = 6;
  s.axial_folds = 2;
  s.top_disc = false;
  s.base_disc = false;
  return s;
}

// The facets of `x` are those of the development: every edge keeps its length, every quad
// stays planar, and the seam closes (edge u -> v joined to v' -> u').
void expect_rigid_and_closed(const CreasePattern& p, const std::vector<Vec3>& x) {
  for (const PatternEdge& e : p.edges) {
    const auto [a, b] = e.vertices;
    EXPECT_NEAR((p.vertices_flat_m[a] - p.vertices_flat_m[b]).norm(), (x[a] - x[b]).norm(), 1e-12);
  }
  for (const auto& f : p.faces) {  // the fourth corner in the first three's plane
    const Vec3 n = (x[f[1]] - x[f[0]]).cross(x[f[2]] - x[f[0]]).normalized();
    EXPECT_NEAR(n.dot(x[f[3]] - x[f[0]]), 0, 1e-12);
  }
  for (const auto& [e0, e1] : p.seams) {
    EXPECT_NEAR((x[p.edges[e0].vertices[0]] - x[p.edges[e1].vertices[1]]).norm(), 0, 1e-12);
    EXPECT_NEAR((x[p.edges[e0].vertices[1]] - x[p.edges[e1].vertices[0]]).norm(), 0, 1e-12);
  }
}

TEST(ConePattern, FoldedFormIsTheFacetedConeAndTheDevelopmentItsIsometry) {
  const ConeSpec s = open_cone();
  const CreasePattern p = cone_crease_pattern(s);
  const int G = 2 * s.pleats;
  // Corners of the base (z = 0, radius R) and top (z = h, radius r) polygons at azimuths
  // 2 pi (k + 1/2) / G; the seam (mid-facet) at R cos(pi / G).
  int base_corners = 0, top_corners = 0;
  for (const Vec3& x : p.vertices_folded_m) {
    const double rad = std::hypot(x.x(), x.y());
    const double a = std::atan2(x.y(), x.x()) * G / (2 * kPi) - 0.5;  // k at a corner
    const bool corner = std::abs(a - std::round(a)) < 1e-9;
    if (std::abs(x.z()) < 1e-12 && corner) {
      EXPECT_NEAR(rad, s.base_radius, 1e-12);
      ++base_corners;
    }
    if (std::abs(x.z() - s.height) < 1e-12 && corner) {
      EXPECT_NEAR(rad, s.top_radius, 1e-12);
      ++top_corners;
    }
  }
  EXPECT_EQ(base_corners, G);
  EXPECT_EQ(top_corners, G);
  // The development: a sector of G generators beta apart, beta the angle between two adjacent
  // corners seen from the apex; the base corners at the slant length from the apex (origin).
  const double z_apex = s.height * s.base_radius / (s.base_radius - s.top_radius);
  const double slant = std::hypot(s.base_radius, z_apex);
  const double beta = 2 * std::asin(s.base_radius * std::sin(kPi / G) / slant);
  double widest = 0;
  for (const Vec2& u : p.vertices_flat_m) {
    if (std::abs(u.norm() - slant) < 1e-12) widest = std::max(widest, std::atan2(u.y(), u.x()));
  }
  EXPECT_NEAR(widest, (G - 0.5) * beta, 1e-12);  // the last generator
  // Every edge as long folded as flat, faces planar, the seam closed.
  ASSERT_EQ(p.seams.size(), static_cast<std::size_t>(s.axial_folds + 1));
  expect_rigid_and_closed(p, p.vertices_folded_m);
}

void expect_flat_foldable(const ConeSpec& s) {
  const CreasePattern p = cone_crease_pattern(s);
  std::map<int, std::vector<int>> around;  // vertex -> its edges
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    for (int v : p.edges[e].vertices) around[v].push_back(static_cast<int>(e));
  }
  int interior = 0;
  for (const auto& [v, edges] : around) {
    const bool inside = std::all_of(edges.begin(), edges.end(),
                                    [&](int e) { return p.edges[e].face_count() == 2; });
    if (!inside) continue;
    ++interior;
    ASSERT_EQ(edges.size(), 4u) << "vertex " << v;
    std::vector<double> dir;
    int mountains = 0, valleys = 0;
    for (int e : edges) {
      const auto [a, b] = p.edges[e].vertices;
      const Vec2 d = p.vertices_flat_m[a == v ? b : a] - p.vertices_flat_m[v];
      dir.push_back(std::atan2(d.y(), d.x()));
      mountains += p.edges[e].assignment == EdgeAssignment::Mountain;
      valleys += p.edges[e].assignment == EdgeAssignment::Valley;
    }
    std::sort(dir.begin(), dir.end());
    const double alternate = (dir[1] - dir[0]) + (dir[3] - dir[2]);  // sectors 1 and 3
    EXPECT_NEAR(alternate, kPi, 1e-12) << "Kawasaki at vertex " << v;
    EXPECT_EQ(std::abs(mountains - valleys), 2) << "Maekawa at vertex " << v;
  }
  EXPECT_EQ(interior, 2 * s.pleats * s.axial_folds);  // every generator on every inner ring
}

TEST(ConePattern, InteriorRingVerticesAreFlatFoldable) {
  expect_flat_foldable(open_cone());
}

// The wrap assignment: generator 0 turned to a mountain, so that 2 x pleats generators at 180
// degrees turn the section once round (pleats + 1 mountains, pleats - 1 valleys), every ring
// vertex still flat-foldable; the fan fold's stack and gathered wall refuse it.
TEST(ConePattern, WrapAssignmentTurnsOneGeneratorAndStaysFlatFoldable) {
  ConeSpec s = open_cone();
  s.wrap = true;
  expect_flat_foldable(s);
  const CreasePattern fan = cone_crease_pattern(open_cone()), wrap = cone_crease_pattern(s);
  ASSERT_EQ(fan.edges.size(), wrap.edges.size());
  int turned = 0, mountains = 0, valleys = 0;
  for (std::size_t e = 0; e < wrap.edges.size(); ++e) {
    const auto [a, b] = wrap.edges[e].vertices;
    const Vec2 d = wrap.vertices_flat_m[b] - wrap.vertices_flat_m[a];
    const Vec2 mid = 0.5 * (wrap.vertices_flat_m[a] + wrap.vertices_flat_m[b]);
    const bool generator = std::abs(d.x() * mid.y() - d.y() * mid.x()) < 1e-12 * d.norm();
    if (!generator || wrap.edges[e].face_count() != 2) continue;  // radial interior edges
    mountains += wrap.edges[e].assignment == EdgeAssignment::Mountain;
    valleys += wrap.edges[e].assignment == EdgeAssignment::Valley;
    if (wrap.edges[e].assignment != fan.edges[e].assignment) {
      ++turned;
      EXPECT_EQ(wrap.edges[e].fold_angle, -fan.edges[e].fold_angle);
    }
  }
  const int bands = s.axial_folds + 1;
  EXPECT_EQ(turned, bands);  // one generator, all along its length
  EXPECT_EQ(mountains, (s.pleats + 1) * bands);
  EXPECT_EQ(valleys, (s.pleats - 1) * bands);
  EXPECT_THROW(cone_fan_stack(s, wrap, 0), InputError);
  EXPECT_THROW(cone_gathered(s, wrap, 0.5), InputError);
}

TEST(ConePattern, OpenEndsLeaveTheirDiscsOut) {
  ConeSpec s = open_cone();
  const int wall = (2 * s.pleats + 1) * (s.axial_folds + 1), disc = 2 * s.pleats + 2;
  EXPECT_EQ(cone_crease_pattern(s).faces.size(), static_cast<std::size_t>(wall));
  EXPECT_EQ(cone_hub_face(s, true), -1);
  EXPECT_EQ(cone_hub_face(s, false), -1);
  s.base_disc = true;
  EXPECT_EQ(cone_crease_pattern(s).faces.size(), static_cast<std::size_t>(wall + disc));
  EXPECT_EQ(cone_hub_face(s, false), wall);
  s.top_disc = true;
  EXPECT_EQ(cone_crease_pattern(s).faces.size(), static_cast<std::size_t>(wall + 2 * disc));
  EXPECT_EQ(cone_hub_face(s, true), wall);
  EXPECT_EQ(cone_hub_face(s, false), wall + disc);
}

TEST(ConePattern, FanStackIsTheFlatFoldedWallAndItsRingsZFold) {
  const ConeSpec s = open_cone();
  CreasePattern p = cone_crease_pattern(s);
  const int G = 2 * s.pleats;
  const double z_apex = s.height * s.base_radius / (s.base_radius - s.top_radius);
  const double slant = std::hypot(s.base_radius, z_apex);
  const double beta = 2 * std::asin(s.base_radius * std::sin(kPi / G) / slant);
  // Rings flat: one facet's place, every vertex at its flat distance from the apex.
  const std::vector<Vec3> flat = cone_fan_stack(s, p, 0);
  expect_rigid_and_closed(p, flat);
  for (std::size_t v = 0; v < flat.size(); ++v) {
    EXPECT_NEAR(flat[v].z(), 0, 1e-15);
    EXPECT_NEAR(flat[v].norm(), p.vertices_flat_m[v].norm(), 1e-12);
    EXPECT_LE(std::abs(std::atan2(flat[v].y(), flat[v].x())), 0.5 * beta + 1e-12);
  }
  // Rings at 90 degrees: each ring crease folded by 90 degrees of its own kind, each
  // generator by 180 degrees.
  p.vertices_folded_m = cone_fan_stack(s, p, 0.5 * kPi);
  expect_rigid_and_closed(p, p.vertices_folded_m);
  int rings = 0;
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    const PatternEdge& edge = p.edges[e];
    if (edge.face_count() != 2) continue;
    const double measured = measured_fold_angle(p, static_cast<int>(e));
    if (std::abs(std::abs(edge.fold_angle) - s.axial_fold_angle) < 1e-12) {
      ++rings;
      EXPECT_NEAR(measured, std::copysign(0.5 * kPi, edge.fold_angle), 1e-9) << "edge " << e;
    } else {
      EXPECT_NEAR(std::abs(measured), kPi, 1e-6) << "edge " << e;
    }
  }
  EXPECT_EQ(rings, s.axial_folds * (G + 1));
  // Rings at 180 degrees: flat folded again.
  for (const Vec3& x : cone_fan_stack(s, p, kPi)) EXPECT_NEAR(x.z(), 0, 1e-12);
  // Only for the open wall.
  ConeSpec closed = s;
  closed.base_disc = true;
  EXPECT_THROW(cone_fan_stack(closed, cone_crease_pattern(closed), 0), InputError);
}

TEST(ConePattern, GatheredWallIsRigidAndFoldsItsGeneratorsTowardTheirKinds) {
  const ConeSpec s = open_cone();
  CreasePattern p = cone_crease_pattern(s);
  const std::vector<Vec3> deployed = p.vertices_folded_m;
  // gather = 0: the deployed cone.
  const std::vector<Vec3> same = cone_gathered(s, p, 0);
  for (std::size_t v = 0; v < same.size(); ++v) {
    EXPECT_NEAR((same[v] - deployed[v]).norm(), 0, 1e-12) << "vertex " << v;
  }
  std::map<int, double> before;
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    if (p.edges[e].face_count() == 2) before[e] = measured_fold_angle(p, static_cast<int>(e));
  }
  p.vertices_folded_m = cone_gathered(s, p, 0.6);
  expect_rigid_and_closed(p, p.vertices_folded_m);
  // Rings stay flat; each generator turns from the deployed pyramid's angle towards its own
  // kind (valleys, even generators, up towards 180 degrees; mountains down towards -180).
  int generators = 0;
  for (const auto& [e, angle] : before) {
    const double now = measured_fold_angle(p, e), target = p.edges[e].fold_angle;
    if (std::abs(std::abs(target) - s.axial_fold_angle) < 1e-12) {
      EXPECT_NEAR(now, 0, 1e-9) << "ring edge " << e;
    } else {
      ++generators;
      EXPECT_GT(now * target, angle * target + 0.5 * std::abs(target)) << "generator edge " << e;
    }
  }
  EXPECT_EQ(generators, 2 * s.pleats * (s.axial_folds + 1));
  // Only for the open wall, and gather in [0, 1).
  EXPECT_THROW(cone_gathered(s, p, 1.0), InputError);
  EXPECT_THROW(cone_gathered(s, p, -0.1), InputError);
  ConeSpec closed = s;
  closed.top_disc = true;
  EXPECT_THROW(cone_gathered(closed, cone_crease_pattern(closed), 0.5), InputError);
}

// Stowed by reflection (docs/folding.md, "The cone stowed by reflection"): the gathered
// wall with its rings made planar by their zigzag, each band below a ring reflected across
// the ring's plane. Closed form of a reflection across horizontal planes: every vertex keeps
// the gathered wall's x and y, the rings are horizontal, the height is the tallest band's;
// the facets stay rigid and the seam closed; each generator changes kind at every ring (the
// Miura vertex's straight pair) and each ring is one kind, alternating ring by ring; every
// ring vertex flat-foldable.
TEST(ConePattern, ReflectedWallIsTheGatheredWallsBandsMirroredAcrossTheirRings) {
  for (const int pleats : {6, 12}) {
    for (const double gather : {0.0, 0.5, 0.9}) {
      SCOPED_TRACE(testing::Message() << pleats << " pleats, gather " << gather);
      ConeSpec s = open_cone();
      s.pleats = pleats;
      s.reflect_gather = gather;
      CreasePattern p = cone_crease_pattern(s);
      const int W = 2 * pleats + 1, B = s.axial_folds + 1;
      auto vid = [&](int ring, int line) { return ring * (W + 1) + line; };
      const std::vector<Vec3> g = cone_gathered(s, p, gather), x = cone_reflected(s, p);
      expect_rigid_and_closed(p, x);
      for (int r = 1; r < B; ++r) {  // interior rings horizontal in the gathered wall
        for (int l = 0; l <= W; ++l) EXPECT_NEAR(g[vid(r, l)].z(), g[vid(r, 0)].z(), 1e-12);
      }
      for (std::size_t v = 0; v < x.size(); ++v) {
        EXPECT_NEAR(x[v].x(), g[v].x(), 1e-12);
        EXPECT_NEAR(x[v].y(), g[v].y(), 1e-12);
      }
      // Each band keeps its height and the bands zigzag about the ring planes: the stowed
      // wall is about one band tall (the end bands' height differs by their flat end rings).
      auto extent = [&](const std::vector<Vec3>& at, int first_ring, int last_ring) {
        double lo = 1e9, hi = -1e9;
        for (int r = first_ring; r <= last_ring; ++r) {
          for (int l = 0; l <= W; ++l)
            lo = std::min(lo, at[vid(r, l)].z()), hi = std::max(hi, at[vid(r, l)].z());
        }
        return hi - lo;
      };
      double tallest = 0;
      for (int b = 0; b < B; ++b) {
        EXPECT_NEAR(extent(x, b, b + 1), extent(g, b, b + 1), 1e-12);
        tallest = std::max(tallest, extent(g, b, b + 1));
      }
      EXPECT_LT(extent(x, 0, B), 1.1 * tallest);
      EXPECT_NEAR(extent(g, 0, B), s.height, 0.2 * s.height);
      // Kinds: measured in the stowed state, as the pattern says.
      p.vertices_folded_m = x;
      std::map<std::pair<int, int>, double> generator;  // (band, generator) -> fold
      std::map<int, std::vector<double>> ring;          // ring -> its chords' folds
      for (std::size_t e = 0; e < p.edges.size(); ++e) {
        const PatternEdge& edge = p.edges[e];
        if (edge.face_count() != 2) continue;
        const double measured = measured_fold_angle(p, static_cast<int>(e));
        EXPECT_NEAR(measured, edge.fold_angle, 1e-12);
        EXPECT_EQ(edge.assignment,
                  measured > 0 ? EdgeAssignment::Valley : EdgeAssignment::Mountain);
        EXPECT_GT(std::abs(measured), 1e-3) << "edge " << e;
        const auto [u, v] = edge.vertices;
        if (u / (W + 1) == v / (W + 1)) {
          ring[u / (W + 1)].push_back(measured);
        } else {
          generator[{std::min(u, v) / (W + 1), u % (W + 1)}] = measured;
        }
      }
      EXPECT_EQ(generator.size(), static_cast<std::size_t>(2 * pleats * B));
      for (const auto& [key, fold] : generator) {
        if (key.first + 1 < B) {
          EXPECT_NEAR(generator.at({key.first + 1, key.second}), -fold, 1e-9);
        }
      }
      ASSERT_EQ(ring.size(), static_cast<std::size_t>(B - 1));
      for (const auto& [r, folds] : ring) {
        for (double f : folds) {
          EXPECT_GT(f * folds.front(), 0) << "ring " << r;
        }
        if (r > 1) {
          EXPECT_LT(folds.front() * ring.at(r - 1).front(), 0) << "ring " << r;
        }
      }
      expect_flat_foldable(s);
    }
  }
  ConeSpec s = open_cone();
  s.reflect_gather = 1.0;
  EXPECT_THROW(cone_crease_pattern(s), InputError);
  s.reflect_gather = 0.5;  // rings 2 mm apart: the zigzag (factor 1.039) would cross the next
  s.axial_folds = 100;
  EXPECT_THROW(cone_crease_pattern(s), InputError);
  s.axial_folds = 2;
  s.reflect_gather = 0.5;
  s.wrap = true;
  EXPECT_THROW(cone_crease_pattern(s), InputError);
  s.wrap = false;
  s.top_disc = true;
  EXPECT_THROW(cone_crease_pattern(s), InputError);
  s.top_disc = false;
  s.reflect_gather = -1;
  EXPECT_THROW(cone_reflected(s, cone_crease_pattern(s)), InputError);
}

}  // namespace cone_pattern_test
}  // namespace finseg
