// The lay-flat tube (issue 13 item 5, docs/fold.md "The lay-flat tube"): the flattened,
// sealed tube's folded coordinates against its development (an exact isometry of planar
// faces), its volume against the closed form of the flattened prism with wedge seals, the
// chamber check, and a pressurised tube rounding out to the linkage's largest section, the
// cyclic polygon.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include "core/error.hpp"
#include "elements/chamber_gas.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "patterns/flat_tube_pattern.hpp"
#include "patterns/pattern_checks.hpp"
#include "pressure_test_util.hpp"
#include "solvers/dofs.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace flat_tube_test {

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

// The sealed tube is a closed chamber without end plates, its volume the flattened prism's
// with two wedge seals (flat_tube_volume) to round-off, at any subdivision; with one face
// left out the chamber check refuses it.
TEST(FlatTube, SealedTubeIsAClosedChamberOfTheFlattenedVolume) {
  const FlatTubeSpec s = small_tube();
  const CreasePattern p = flat_tube_crease_pattern(s);
  for (int n : {1, 2, 3}) {
    Model m = tube_model(p, n, 0.01);
    m.chambers.push_back(test::whole_model_chamber(m, "tube"));
    prepare_chambers(m);
    EXPECT_NEAR(m.chambers[0].initial_volume / flat_tube_volume(s), 1, 1e-12) << n;
  }
  Model m = tube_model(p, 1, 0.01);
  ChamberDef open = test::whole_model_chamber(m, "tube");
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
  for (std::size_t a = 0; a < ring.size(); ++a) {
    const Vec3 &u = ring[a], &v = ring[(a + 1) % ring.size()];
    area2 += u.x() * v.z() - u.z() * v.x();
  }
  return std::abs(area2) / 2;
}

// The flattened tube under a step pressure of 1 kPa (generalized-alpha without numerical
// dissipation, no material damping, the first seal row clamped), 0.3 ms: it rounds out
// (its middle section, measured from the cells' corners, grows from width x gap), and the
// gas work p (V - V0) equals the structure's elastic plus kinetic energy within 0.1 % (energy
// conservation; the scheme's error is second order in its steps). The section does not reach
// the cyclic polygon (flat_tube_round_area) in this time: examples/tube/flat_inflate.yaml
// runs the whole deployment (docs/gas.md).
TEST(FlatTube, PressurisedFlatTubeRoundsOutConservingEnergy) {
  FlatTubeSpec s;
  s.layer_facets = 4;
  s.rows = 6;
  s.width = 0.04;
  s.gap = 1e-3;
  s.length = 0.1;
  const CreasePattern p = flat_tube_crease_pattern(s);
  Model m = tube_model(p, 1, 0.002, flat_tube_row_faces(s, 0));
  ChamberDef c = test::whole_model_chamber(m, "tube");
  const double pressure = 1e3;
  c.prescribed.pressure = pressure;
  m.chambers.push_back(c);
  validate(m);
  prepare_chambers(m);
  State st = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Implicit;
  set.scheme = ImplicitScheme::GeneralizedAlpha;
  set.rho_inf = 1;
  set.t_end = 3e-4;
  set.output_interval = 1e-4;
  set.dt_max = 1e-5;
  double last_area = 0;
  const double dy = (s.length - 2 * s.seal_length) / (s.rows - 2);
  const double y_mid = std::hypot(s.seal_length, s.gap / 2) + (s.rows / 2 - 1) * dy;
  const double perimeter = 2 * s.width + 2 * s.gap;
  const SolverStats stats = run_solver(m, st, set, [&](const State& now, const BodyForces& f) {
    const ChamberGas& g = now.chambers[0];
    const double area = section_area(m, now, y_mid, perimeter);
    if (now.t == 0) {
      EXPECT_NEAR(area / (s.width * s.gap), 1, 1e-9);
    } else {
      EXPECT_GT(area, last_area) << now.t;
      EXPECT_NEAR(g.work, pressure * (g.volume - m.chambers[0].initial_volume), 1e-12 * g.work);
      EXPECT_NEAR((f.potential_energy + kinetic_energy(m, now)) / g.work, 1, 1e-3) << now.t;
    }
    last_area = area;
    std::printf(
        "t %.1e: section %.4e m^2 (cyclic polygon %.4e), volume %.4e, work %.4e, "
        "(elastic + kinetic) / work %.5f\n",
        now.t, area, flat_tube_round_area(s), g.volume, g.work,
        g.work > 0 ? (f.potential_energy + kinetic_energy(m, now)) / g.work : 0.0);
  });
  ASSERT_EQ(stats.status, "ok") << stats.message;
  EXPECT_GT(st.chambers[0].volume, 1.5 * flat_tube_volume(s));
}

}  // namespace flat_tube_test
}  // namespace finseg
