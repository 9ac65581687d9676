// The lay-flat tube (issue 13 item 5, docs/fold.md "The lay-flat tube"): the flattened,
// sealed tube's folded coordinates against its development (an exact isometry of planar
// faces), its volume against the closed form of the flattened prism with wedge seals, the
// chamber check, and a pressurised tube rounding out to the linkage's largest section, the
// cyclic polygon.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>

#include "core/error.hpp"
#include "elements/chamber_gas.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "patterns/flat_tube_pattern.hpp"
#include "patterns/pattern_checks.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace {

FlatTubeSpec small_tube() {
  FlatTubeSpec s;
  s.layer_facets = 3;
  s.rows = 5;
  s.width = 0.03;
  s.gap = 1e-3;
  s.length = 0.1;
  return s;
}

// Every edge, and both diagonals of every face, as long folded as flat: the folded state is
// an isometry of the development on every (planar, checked by validate_pattern) face.
TEST(FlatTube, FoldedCoordinatesAreAnIsometryOfPlanarFaces) {
  const FlatTubeSpec s = small_tube();
  CreasePattern p = flat_tube_crease_pattern(s);
  validate_pattern(p, "<flat tube>");
  const int k = s.layer_facets, N = 2 * k + 2;
  // Straight rows N quadrilaterals, seal rows 2 k quadrilaterals and 2 x 3 triangles.
  ASSERT_EQ(p.faces.size(), static_cast<std::size_t>((s.rows - 2) * N + 2 * (2 * k + 6)));
  double worst = 0;
  auto compare = [&](int a, int b) {
    const double flat = (p.vertices_flat_m[a] - p.vertices_flat_m[b]).norm();
    const double folded = (p.vertices_folded_m[a] - p.vertices_folded_m[b]).norm();
    worst = std::max(worst, std::abs(folded - flat));
  };
  for (const auto& f : p.faces) {
    for (std::size_t a = 0; a < f.size(); ++a) {
      for (std::size_t b = a + 1; b < f.size(); ++b) compare(f[a], f[b]);
    }
  }
  EXPECT_LT(worst, 1e-15);
  // Planar to round-off: each quadrilateral's fourth corner on the plane of the other three.
  for (const auto& f : p.faces) {
    if (f.size() != 4) continue;
    const Vec3 &a = p.vertices_folded_m[f[0]], &b = p.vertices_folded_m[f[1]],
               &c = p.vertices_folded_m[f[2]], &d = p.vertices_folded_m[f[3]];
    const Vec3 n = (b - a).cross(c - a).normalized();
    EXPECT_LT(std::abs(n.dot(d - a)), 1e-16);
  }
  // Every seam joins points that coincide folded (validate_pattern: within 1e-6 of the size);
  // here exactly: both layers' end lines lie at z = 0 and y = 0 or length.
  for (const auto& seam : p.seams) {
    const PatternEdge &a = p.edges[seam[0]], &b = p.edges[seam[1]];
    EXPECT_LT((p.vertices_folded_m[a.vertices[0]] - p.vertices_folded_m[b.vertices[1]]).norm(),
              1e-17);
    EXPECT_LT((p.vertices_folded_m[a.vertices[1]] - p.vertices_folded_m[b.vertices[0]]).norm(),
              1e-17);
  }
  // One seam per row along the tube; per end k layer pairs and 2 gusset halves.
  EXPECT_EQ(p.seams.size(), static_cast<std::size_t>(s.rows + 2 * (k + 2)));
  // Rolled and sealed, it is a sphere: V - E + F = 2 with every seam's two edges one edge and
  // the vertices they join one vertex (the seal's corners: 4 development vertices per corner).
  std::map<std::pair<long, long>, int> unique;
  for (const Vec3& x : p.vertices_folded_m) {
    unique[{std::lround(x.x() * 1e9) * 1000003 + std::lround(x.z() * 1e9),
            std::lround(x.y() * 1e9)}] = 1;
  }
  const int v = static_cast<int>(unique.size());
  const int e = static_cast<int>(p.edges.size() - p.seams.size());
  EXPECT_EQ(v - e + static_cast<int>(p.faces.size()), 2);
}

// The model of the pattern: one cell per face (or n x n), the whole surface one chamber.
Model tube_model(const CreasePattern& p, int subdivisions, double crease_stiffness,
                 const std::vector<int>& fixed_faces = {}) {
  PatternSheetSpec spec;
  spec.thickness = 1e-4;
  spec.youngs_modulus = 3e9;
  spec.poisson_ratio = 0.3;
  spec.density = 1000;
  spec.subdivisions = subdivisions;
  spec.mountain_law = std::make_shared<LinearCreaseLaw>(crease_stiffness, 0.0);
  spec.valley_law = std::make_shared<LinearCreaseLaw>(crease_stiffness, 0.0);
  spec.laws_rest_at_pattern = true;
  spec.fixed_faces = fixed_faces;
  return build_pattern_model(p, spec, "<flat tube>");
}

ChamberDef whole_chamber(const Model& m) {
  ChamberDef c;
  c.name = "tube";
  for (std::size_t b = 0; b < m.bodies.size(); ++b) c.faces.push_back({static_cast<int>(b), true});
  c.gas = GasModel::Prescribed;
  return c;
}

// The sealed tube is a closed chamber without end plates, its volume the flattened prism's
// with two wedge seals (flat_tube_volume) to round-off, at any subdivision; with one face
// left out the chamber check refuses it.
TEST(FlatTube, SealedTubeIsAClosedChamberOfTheFlattenedVolume) {
  const FlatTubeSpec s = small_tube();
  const CreasePattern p = flat_tube_crease_pattern(s);
  for (int n : {1, 2, 3}) {
    Model m = tube_model(p, n, 0.01);
    m.chambers.push_back(whole_chamber(m));
    prepare_chambers(m);
    EXPECT_NEAR(m.chambers[0].initial_volume / flat_tube_volume(s), 1, 1e-12) << n;
  }
  Model m = tube_model(p, 1, 0.01);
  ChamberDef open = whole_chamber(m);
  open.faces.erase(open.faces.begin() + 7);
  m.chambers.push_back(open);
  EXPECT_THROW(prepare_chambers(m), InputError);
}

TEST(FlatTube, RefusesSpecsOutOfRange) {
  auto refused = [](auto change, const char* field) {
    FlatTubeSpec s = small_tube();
    change(s);
    try {
      flat_tube_crease_pattern(s);
      ADD_FAILURE() << field << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  };
  refused([](FlatTubeSpec& s) { s.layer_facets = 1; }, "layer_facets");
  refused([](FlatTubeSpec& s) { s.rows = 2; }, "rows");
  refused([](FlatTubeSpec& s) { s.width = 0; }, "width");
  refused([](FlatTubeSpec& s) { s.gap = 0.011; }, "gap");  // wider than a facet (10 mm)
  refused([](FlatTubeSpec& s) { s.gap = std::nan(""); }, "gap");
  refused([](FlatTubeSpec& s) { s.length = -1; }, "length");
}

// The cyclic polygon's area against closed forms: 2 k equal sides and two of length -> 0 is
// the regular 2k-gon of that side; all 2k + 2 sides equal is the regular (2k + 2)-gon.
TEST(FlatTube, RoundAreaIsTheCyclicPolygons) {
  FlatTubeSpec s = small_tube();
  const double w = s.width / s.layer_facets;
  auto regular = [](int n, double side) { return n * side * side / (4 * std::tan(kPi / n)); };
  s.gap = 1e-9 * w;
  EXPECT_NEAR(flat_tube_round_area(s) / regular(6, w), 1, 1e-8);
  s.gap = w * (1 - 1e-15);
  EXPECT_NEAR(flat_tube_round_area(s) / regular(8, w), 1, 1e-12);
}

// Cross-section area at the flat sheet's line y_M: the section's corners (cell corners on
// that line, the two cells' copies averaged), ordered around the tube, in the x-z plane.
double section_area(const Model& m, const State& s, double y_M, double perimeter) {
  std::map<long, std::pair<Vec3, int>> corners;  // material x (nm) -> sum, count
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const BodyDef& body = m.bodies[b];
    for (const Vec2& c : body.outline_B) {
      const Vec2 material = *body.centroid_M + c;
      if (std::abs(material.y() - y_M) > 1e-9) continue;
      const long key = std::lround(std::fmod(material.x(), perimeter - 1e-9) * 1e9);
      auto& [sum, count] = corners.try_emplace(key, Vec3::Zero(), 0).first->second;
      sum += s.p_W[b] + s.R_WB[b] * Vec3(c.x(), c.y(), 0);
      ++count;
    }
  }
  double area2 = 0;
  std::vector<Vec3> ring;
  for (const auto& [key, sc] : corners) ring.push_back(sc.first / sc.second);
  if (std::getenv("FT_RING"))
    for (const Vec3& r : ring) std::printf("ring %.5f %.5f %.5f\n", r.x(), r.y(), r.z());
  for (std::size_t a = 0; a < ring.size(); ++a) {
    const Vec3 &u = ring[a], &v = ring[(a + 1) % ring.size()];
    area2 += u.x() * v.z() - u.z() * v.x();
  }
  return std::abs(area2) / 2;
}

// Pressurised (static, load-stepped), the flattened tube rounds out: its middle section, two
// diameters from the seals, reaches the cyclic polygon of its sides, the largest area the
// linkage can enclose, which a uniform pressure maximises (p dV with rigid facets). Within
// 1 %: the creases' moments (0.002 N m/rad/m against p w^2 = 0.1 N m/m: 3 % of the load's
// moment, whose effect on the area is second order at the maximum) and the hoop stretch
// p rho / (E t) = 4e-5; the seals keep the ends flat (membrane strain there), which the
// volume shows: between the flattened one and the round section times the length.
TEST(FlatTube, PressurisedFlatTubeRoundsOutToTheCyclicPolygon) {
  FlatTubeSpec s;
  s.layer_facets = 4;
  s.rows = 10;
  s.width = 0.04;
  s.gap = 1e-3;
  s.length = 0.2;
  const CreasePattern p = flat_tube_crease_pattern(s);
  std::vector<int> fixed = flat_tube_row_faces(s, 0);
  if (std::getenv("FT_BOTH"))
    for (int f : flat_tube_row_faces(s, s.rows - 1)) fixed.push_back(f);
  Model m = tube_model(p, 1, std::getenv("FT_C") ? std::atof(std::getenv("FT_C")) : 0.002, fixed);
  ChamberDef c = whole_chamber(m);
  c.prescribed.pressure = 1e3;
  m.chambers.push_back(c);
  validate(m);
  prepare_chambers(m);
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const ElementDef& el = m.elements[e];
    const BodyDef &a = m.bodies[el.inner], &b = m.bodies[el.outer];
    const Vec3 d = (a.p0_W + a.R0_WB * el.c_inner_B) - (b.p0_W + b.R0_WB * el.c_outer_B);
    const Vec3 zF = (b.R0_WB * el.R_outer_F).transpose() * d - el.z0_F;
    if (zF.norm() > 1e-9)
      std::printf("element %zu (%d %d) gap %.3e\n", e, el.inner, el.outer, zF.norm());
  }
  State st = initial_state(m);
  SolverSettings set;
  if (std::getenv("FT_T")) {
    set.kind = SolverKind::Implicit;
    set.t_end = std::atof(std::getenv("FT_T"));
    set.output_interval = set.t_end;
    set.dt_max = 1e-4;
  } else
    set.kind = SolverKind::Static;
  set.load_steps = std::getenv("FT_N") ? std::atoi(std::getenv("FT_N")) : 20;
  const SolverStats stats = run_solver(m, st, set, nullptr);
  std::printf("steps %ld newton %ld wall %.2f\n", stats.steps, stats.newton_iterations,
              stats.wall_seconds);
  ASSERT_EQ(stats.status, "ok") << stats.message;
  const double dy = (s.length - 2 * s.seal_length) / (s.rows - 2);
  const double seal = std::hypot(s.seal_length, s.gap / 2);  // its development length
  const double y_mid = seal + (s.rows / 2 - 1) * dy, perimeter = 2 * s.width + 2 * s.gap;
  const double round = flat_tube_round_area(s);
  EXPECT_NEAR(section_area(m, initial_state(m), y_mid, perimeter) / (s.width * s.gap), 1, 1e-9);
  const double area = section_area(m, st, y_mid, perimeter);
  std::printf("middle section %.6e m^2, cyclic polygon %.6e (%+.2e); volume %.6e, flat %.6e\n",
              area, round, area / round - 1, st.chambers[0].volume, flat_tube_volume(s));
  EXPECT_NEAR(area / round, 1, 0.01);
  EXPECT_GT(st.chambers[0].volume, 10 * flat_tube_volume(s));
  EXPECT_LT(st.chambers[0].volume, round * s.length);
}

}  // namespace
}  // namespace finseg
