// Cutting crease patterns into segments (patterns/segment_mesh.hpp): n x n cells, a target
// segment size, grading towards folded creases, and crease laws per edge list. Checks are
// geometric (cells cover the faces, neighbouring faces meet side to side, the geometric
// grading's closed form) and mechanical: a strip of panels hinged by creases under an end
// moment, whose last cell turns by M / K for every crease plus the beam's M x / (E I) over
// the length of plate between the clamp and that cell's centroid, on any of these meshes.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "cli_test_util.hpp"
#include "core/error.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "model/segment_shape.hpp"
#include "patterns/fold_format.hpp"
#include "patterns/segment_mesh.hpp"
#include "scene/scene_reader.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace pattern_subdivision_test {

// Cells convex and covering each face exactly; every interior cell side shared by two cells
// (Euler's V - E + F = 1 for a disc fails at a hanging vertex); `on_edges` cell sides on the
// pattern's interior edges.
void expect_conforming_cover(const CreasePattern& p, const SegmentMesh& mesh,
                             std::size_t on_edges) {
  std::vector<double> area(p.faces.size(), 0.0);
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    Outline o;
    for (int v : mesh.cells[c]) o.push_back(mesh.flat_m[v]);
    EXPECT_EQ(convexity_problem(o, 1e-12), "") << "cell " << c;
    area[mesh.cell_face[c]] += polygon_area(o);
  }
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    Outline face;
    for (int v : p.faces[f]) face.push_back(p.vertices_flat_m[v]);
    EXPECT_NEAR(area[f], polygon_area(face), 1e-12) << "face " << f;
  }
  std::size_t sides = 0, linked_on_edges = 0;
  for (const auto& c : mesh.cells) sides += c.size();
  for (const CellLink& l : mesh.links) linked_on_edges += l.pattern_edge >= 0;
  const std::size_t boundary = sides - 2 * mesh.links.size();
  EXPECT_EQ(mesh.flat_m.size() - (mesh.links.size() + boundary) + mesh.cells.size(), 1u);
  EXPECT_EQ(linked_on_edges, on_edges);
}

CreasePattern with_edges(CreasePattern p) {
  p.edges = edges_from_faces(p.faces);
  derive_edge_faces(p, "<mesh>");
  return p;
}

// A triangle, a quadrilateral and a pentagon sharing sides.
CreasePattern mixed_faces() {
  CreasePattern p;
  p.vertices_flat_m = {{0, 0}, {2, 0}, {2, 1}, {0, 1}, {1, 2}, {3, 0.5}, {3, 1.6}, {2.4, 2.2}};
  p.faces = {{0, 1, 2, 3}, {3, 2, 4}, {1, 5, 6, 7, 2}};
  return with_edges(p);
}

// `panels` rectangles a x w in a row along x; edge k + 1 of the row (between panels k and
// k + 1) gets assignments[k].
CreasePattern strip_of_panels(int panels, double a, double w,
                              const std::vector<EdgeAssignment>& assignments) {
  CreasePattern p;
  for (int k = 0; k <= panels; ++k) {
    p.vertices_flat_m.push_back({k * a, 0});
    p.vertices_flat_m.push_back({k * a, w});
  }
  for (int k = 0; k < panels; ++k) p.faces.push_back({2 * k, 2 * k + 2, 2 * k + 3, 2 * k + 1});
  p = with_edges(p);
  for (PatternEdge& e : p.edges) {
    const int u = e.vertices[0], v = e.vertices[1];
    if (e.assignment == EdgeAssignment::Flat && u / 2 == v / 2) {
      e.assignment = assignments[u / 2 - 1];
    }
  }
  return p;
}

// Cell widths along x of face f's cells on the line y = 0 (cells touching it), in order.
std::vector<double> widths_along_x(const SegmentMesh& mesh, int f) {
  std::vector<std::pair<double, double>> spans;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    if (mesh.cell_face[c] != f) continue;
    double lo = INFINITY, hi = -INFINITY, ymin = INFINITY;
    for (int v : mesh.cells[c]) {
      lo = std::min(lo, mesh.flat_m[v].x());
      hi = std::max(hi, mesh.flat_m[v].x());
      ymin = std::min(ymin, mesh.flat_m[v].y());
    }
    if (ymin == 0) spans.push_back({lo, hi - lo});
  }
  std::sort(spans.begin(), spans.end());
  std::vector<double> w;
  for (const auto& s : spans) w.push_back(s.second);
  return w;
}

TEST(SegmentMesh, FacesMeetSideToSideAndCoverThePattern) {
  // Every pattern edge gets n cell sides, cells cover each face exactly, and every interior
  // side has two cells.
  const CreasePattern p = mixed_faces();
  for (int n : {1, 3}) expect_conforming_cover(p, subdivide_pattern(p, n), 2u * n);
}

// Subdivision::triangles: each quadrilateral cell four triangles about the mean of its
// corners; triangles and larger faces cut as before; still a conforming cover.
TEST(SegmentMesh, TriangleCellsCutEachQuadrilateralCellInFour) {
  const CreasePattern p = mixed_faces();
  for (int n : {1, 3}) {
    Subdivision s;
    s.n = n;
    const SegmentMesh quads = subdivide_pattern(p, s);
    s.triangles = true;
    const SegmentMesh tris = subdivide_pattern(p, s);
    std::size_t four_sided = 0;
    for (const auto& c : quads.cells) four_sided += c.size() == 4;
    EXPECT_EQ(four_sided, static_cast<std::size_t>(n * n));  // the quadrilateral face's
    EXPECT_EQ(tris.cells.size(), quads.cells.size() + 3 * four_sided);
    for (const auto& c : tris.cells) EXPECT_EQ(c.size(), 3u);
    EXPECT_EQ(planned_cell_count(p, edge_cell_counts(p, s), true),
              static_cast<double>(tris.cells.size()));
    expect_conforming_cover(p, tris, 2u * n);
  }
}

TEST(SegmentMesh, TargetSizeBoundsEveryCellSideAlongTheEdges) {
  // Rectangles 2 x 0.5 m at 0.3 m: ceil(2 / 0.3) = 7 cells along, ceil(0.5 / 0.3) = 2 across.
  const CreasePattern row = strip_of_panels(2, 2.0, 0.5, {EdgeAssignment::Flat});
  Subdivision s;
  s.segment_size = 0.3;
  const SegmentMesh mesh = subdivide_pattern(row, s);
  EXPECT_EQ(mesh.cells.size(), 2u * 7 * 2);
  EXPECT_EQ(planned_cell_count(row, edge_cell_counts(row, s)), 28.0);
  expect_conforming_cover(row, mesh, 2);
  // Mixed faces: one count per class of edges, each side at most the target.
  const CreasePattern p = mixed_faces();
  for (double size : {0.7, 0.25}) {
    s.segment_size = size;
    const SegmentMesh m = subdivide_pattern(p, s);
    const std::vector<int> counts = edge_cell_counts(p, s);
    EXPECT_EQ(planned_cell_count(p, counts), static_cast<double>(m.cells.size()));
    double longest_edge_side = 0;
    for (const CellLink& l : m.links) {
      if (l.pattern_edge >= 0) {
        longest_edge_side = std::max(longest_edge_side, (m.flat_m[l.b] - m.flat_m[l.a]).norm());
      }
    }
    EXPECT_LE(longest_edge_side, size * (1 + 1e-12));
    // Classes: the quadrilateral's sides (0,1) and (2,3) with the triangle's, its sides
    // (1,2) and (3,0) with the pentagon's; the longest edge of a class sets its count.
    const auto count = [&](int u, int v) {
      for (std::size_t e = 0; e < p.edges.size(); ++e) {
        const auto [a, b] = p.edges[e].vertices;
        if ((a == u && b == v) || (a == v && b == u)) return counts[e];
      }
      return -1;
    };
    const auto cells_for = [&](double len) { return static_cast<int>(std::ceil(len / size)); };
    EXPECT_EQ(count(0, 1), cells_for(2.0));
    for (const auto& [u, v] : {std::pair{2, 3}, {2, 4}, {4, 3}})
      EXPECT_EQ(count(u, v), count(0, 1));
    EXPECT_EQ(count(1, 2), cells_for(std::hypot(0.4, 1.2)));  // the pentagon's (7,2)
    for (const auto& [u, v] : {std::pair{3, 0}, {1, 5}, {5, 6}, {6, 7}, {7, 2}}) {
      EXPECT_EQ(count(u, v), count(1, 2));
    }
    expect_conforming_cover(p, m, count(2, 3) + count(1, 2));
  }
  // Too fine for the allowed cell count: refused, naming the field.
  s.segment_size = 1e-6;
  EXPECT_THROW(edge_cell_counts(p, s, "<scene>", "pattern.segment_size", 4096), InputError);
}

TEST(SegmentMesh, GradedTowardsFoldedCreasesOnly) {
  // Three panels: a valley crease between the first two, a flat (unfolded) F edge between
  // the last two. Along the first two panels the cells shrink geometrically towards the
  // valley, the one next to it 1/r of the largest; the third panel stays uniform, and so do
  // the cells across (the crease is straight: its own ends are not graded).
  const double r = 4;
  const CreasePattern p =
      strip_of_panels(3, 1.0, 0.2, {EdgeAssignment::Valley, EdgeAssignment::Flat});
  Subdivision s;
  s.n = 8;
  s.crease_refinement = r;
  const SegmentMesh mesh = subdivide_pattern(p, s);
  expect_conforming_cover(p, mesh, 2u * 8);
  const std::vector<double> w0 = widths_along_x(mesh, 0), w1 = widths_along_x(mesh, 1),
                            w2 = widths_along_x(mesh, 2);
  ASSERT_EQ(w0.size(), 8u);
  ASSERT_EQ(w1.size(), 8u);
  // Geometric grading: weights r^(min(1, d / 3.5)) / r at d cells from the crease.
  double total = 0;
  for (int j = 0; j < 8; ++j) total += std::pow(r, std::min(1.0, j / 3.5)) / r;
  for (int j = 0; j < 8; ++j) {
    const double expected = std::pow(r, std::min(1.0, j / 3.5)) / r / total;
    EXPECT_NEAR(w1[j], expected, 1e-12) << j;      // panel 1 starts at the valley
    EXPECT_NEAR(w0[7 - j], expected, 1e-12) << j;  // panel 0 ends at it
    EXPECT_NEAR(w2[j], 1.0 / 8, 1e-12) << j;
  }
  EXPECT_NEAR(w1.back() / w1.front(), r, 1e-9);
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    for (int v : mesh.cells[c]) {
      const double y = mesh.flat_m[v].y() / 0.2 * 8;
      EXPECT_NEAR(y, std::round(y), 1e-9) << "uniform across";
    }
  }
}

// The strip of four 50 x 10 mm panels: the first clamped, F between it and the next, then
// two valley creases; a dead end moment about y on the last cell (one cell across).
constexpr double kA = 0.05, kW = 0.01, kT = 2e-4, kE = 2e9, kM = 5e-5;
constexpr double kK1 = 0.02, kK2 = 0.05;  // N m/rad per m of crease: valley law, listed edge

CreasePattern creased_strip() {
  return strip_of_panels(4, kA, kW,
                         {EdgeAssignment::Flat, EdgeAssignment::Valley, EdgeAssignment::Valley});
}

// Index of the strip's edge across at x = k a.
int edge_across(const CreasePattern& p, int k) {
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    if (p.edges[e].vertices[0] / 2 == k && p.edges[e].vertices[1] / 2 == k) return e;
  }
  return -1;
}

std::string strip_scene(const std::string& discretisation, const std::string& extra) {
  return fmt::format(
      "material: {{youngs_modulus: {}, poisson_ratio: 0, density: 500}}\n"
      "sheet: {{thickness: {}}}\n"
      "pattern:\n"
      "  file: strip.fold\n"
      "  {}\n"
      "  valley_law: {{type: linear, stiffness: {}, rest_angle_deg: 0}}\n"
      "{}"
      "fixtures: {{panels: [1]}}\n"
      "solver: {{type: static}}\n",
      kE, kT, discretisation, kK1, extra);
}

std::string edge_law(int edge) {
  return fmt::format(
      "  crease_laws:\n    - {{edges: [{}], law: {{type: linear, stiffness: {}, "
      "rest_angle_deg: 0}}}}\n",
      edge, kK2);
}

// Turn of the last cell (largest centroid x) about y under the end moment, rad.
double end_turn(Model m) {
  int last = 0;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    if (m.bodies[b].p0_W.x() > m.bodies[last].p0_W.x()) last = static_cast<int>(b);
  }
  LoadDef load;
  load.body = last;
  load.moment = Vec3(0, kM, 0);
  m.loads = {load};
  State s = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Static;
  const SolverStats st = run_solver(m, s, set, nullptr);
  EXPECT_EQ(st.status, "ok") << st.message;
  const Mat3& R = s.R_WB[last];
  return std::abs(std::atan2(R(0, 2), R(0, 0)));
}

// The continuum strip's end turn: a beam from the clamp (x = a) to the end (x = 4 a) and each
// crease folding by M / (k w).
double beam_turn(bool listed_law) {
  const double EI = kE * kT * kT * kT * kW / 12;
  return kM * (3 * kA / EI + 1 / (kK1 * kW) + 1 / ((listed_law ? kK2 : kK1) * kW));
}

// Relative error of the last cell's turn against beam_turn, crease sides with their law in
// series with the plate's bending across them (second order at creases).
double strip_error(const Subdivision& cut, bool listed_law, std::size_t* cells = nullptr) {
  const CreasePattern p = creased_strip();
  PatternSheetSpec spec;
  spec.thickness = kT;
  spec.youngs_modulus = kE;
  spec.poisson_ratio = 0;
  spec.density = 500;
  spec.subdivisions = cut.n;
  spec.segment_size = cut.segment_size;
  spec.crease_refinement = cut.crease_refinement;
  spec.valley_law = std::make_shared<LinearCreaseLaw>(kK1, 0.0);
  if (listed_law) {
    spec.edge_laws = {{{edge_across(p, 3)}, std::make_shared<LinearCreaseLaw>(kK2, 0.0)}};
  }
  spec.crease_bending_in_series = true;
  spec.fixed_faces = {0};
  const Model m = build_pattern_model(p, spec);
  if (cells) *cells = m.bodies.size();
  return end_turn(m) / beam_turn(listed_law) - 1;
}

TEST(PatternSubdivision, CreasedStripUnderEndMomentConvergesOnSizedAndGradedMeshes) {
  // The last cell's turn converges to the beam's end turn as the segment size halves, on
  // uniform and graded cells alike, at first order: the turn is the rigid end cell's, whose
  // own bending its correction charges to its one joint (measured: uniform -2.9 / -1.4 / -0.53 %,
  // graded 3:1 -3.5 / -1.7 / -0.10 % at 12 / 6 / 3 mm).
  for (const double refinement : {1.0, 3.0}) {
    double last = 0;
    for (const double size : {0.012, 0.006, 0.003}) {
      Subdivision cut;
      cut.segment_size = size;
      cut.crease_refinement = refinement;
      std::size_t cells = 0;
      const double err = strip_error(cut, refinement > 1, &cells);
      if (refinement == 1) {
        EXPECT_EQ(cells, 4 * std::ceil(kA / size) * std::ceil(kW / size));
      }
      if (last != 0) {
        EXPECT_LT(std::abs(err), 0.55 * std::abs(last)) << size;
      }
      last = err;
      ::testing::Test::RecordProperty(fmt::format("r{}_size{}_rel_error", refinement, size),
                                      fmt::format("{:.3e}", err));
    }
    EXPECT_LT(std::abs(last), 0.01);
  }
}

TEST(PatternSubdivision, SceneCreaseLawsReachTheirEdge) {
  // The same strip from a scene, the crease laws alone on the crease sides: changing the law
  // of the listed crease changes the end's turn by exactly M / (k1 w) - M / (k2 w) (the
  // moment through each crease is M, whatever the cells do).
  const test::TempDir dir;
  const CreasePattern p = creased_strip();
  write_fold((dir.path() / "strip.fold").string(), p);
  const std::string file = (dir.path() / "strip.yaml").string();
  const std::string cut = "segment_size: 0.012\n  crease_refinement: 3";
  const double base = end_turn(parse_scene(strip_scene(cut, ""), file).model);
  const double listed =
      end_turn(parse_scene(strip_scene(cut, edge_law(edge_across(p, 3))), file).model);
  EXPECT_NEAR((base - listed) / (kM / (kK1 * kW) - kM / (kK2 * kW)), 1, 1e-6);
}

TEST(PatternSubdivision, SceneCellsTrianglesCutEachCellInFour) {
  const test::TempDir dir;
  write_fold((dir.path() / "strip.fold").string(), creased_strip());
  const std::string file = (dir.path() / "strip.yaml").string();
  const Model quads = parse_scene(strip_scene("subdivisions: 2", ""), file).model;
  const Model tris =
      parse_scene(strip_scene("subdivisions: 2\n  cells: triangles", ""), file).model;
  EXPECT_EQ(tris.bodies.size(), 4 * quads.bodies.size());
  for (const BodyDef& b : tris.bodies) EXPECT_EQ(material_outline(b).size(), 3u);
}

TEST(PatternSubdivision, BadSubdivisionsAndEdgeListsAreRefusedNamingTheField) {
  const test::TempDir dir;
  const CreasePattern p = creased_strip();
  write_fold((dir.path() / "strip.fold").string(), p);
  const std::string scene = (dir.path() / "strip.yaml").string();
  const auto refused = [&](const std::string& d, const std::string& extra, const std::string& field,
                           const std::string& why) {
    try {
      parse_scene(strip_scene(d, extra), scene);
      ADD_FAILURE() << "accepted: " << field;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), scene);
      EXPECT_EQ(e.field(), field) << e.what();
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  refused("segment_size: 0", "", "pattern.segment_size", "> 0");
  refused("subdivisions: 2\n  segment_size: 0.01", "", "pattern.segment_size", "either");
  refused("crease_refinement: 0.5", "", "pattern.crease_refinement", "[1, 100]");
  refused("cells: hexagons", "", "pattern.cells", "allowed: quadrilaterals, triangles");
  refused("segment_size: 1e-7", "", "pattern.segment_size", "at most 4096");
  refused("subdivisions: 1", edge_law(99), "pattern.crease_laws[0].edges", "does not exist");
  refused("subdivisions: 1", edge_law(0), "pattern.crease_laws[0].edges", "'B'");
  refused("subdivisions: 1",
          fmt::format("  crease_laws:\n    - {{edges: [{0}], law: {{type: linear, stiffness: 1, "
                      "rest_angle_deg: 0}}}}\n    - {{edges: [{0}], law: {{type: linear, "
                      "stiffness: 2, rest_angle_deg: 0}}}}\n",
                      edge_across(p, 2)),
          "pattern.crease_laws[1].edges", "listed twice");
  refused("subdivisions: 1", "  crease_laws:\n    - {edges: []}\n", "pattern.crease_laws[0].edges",
          "empty");
  refused("subdivisions: 1", "  crease_laws:\n    - {edges: [3]}\n", "pattern.crease_laws[0].law",
          "missing");
}

}  // namespace pattern_subdivision_test
}  // namespace finseg
