// Seams (docs/fold.md, "Seams"): a sheet glued along two of its boundary edges. A rectangle
// rolled into a tube closes into a ring; a plate cut in two and joined again by a seam is the
// uncut plate to round-off; bad seams are refused naming file, field and index.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/error.hpp"
#include "elements/assemble.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "pattern_test_util.hpp"
#include "patterns/fold_format.hpp"
#include "patterns/pattern_checks.hpp"
#include "patterns/segment_mesh.hpp"
#include "patterns/tube_pattern.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace pattern_seams_test {

// Crease laws at rest in the rolled tube (the element's angle is FOLD's with the opposite
// sign: +360 / facets degrees).
PatternSheetSpec tube_spec(int n, int facets) {
  PatternSheetSpec spec;
  spec.thickness = 1e-3;
  spec.youngs_modulus = 1e9;
  spec.subdivisions = n;
  spec.mountain_law = std::make_shared<LinearCreaseLaw>(1.0, 2 * kPi / facets);
  return spec;
}

TEST(PatternSeams, RolledRectangleClosesIntoARing) {
  const int facets = 8, rows = 3;
  CreasePattern p = tube_crease_pattern(facets, rows, 0.05, 0.2);
  validate_pattern(p, "<tube>");
  ASSERT_EQ(p.seams.size(), static_cast<std::size_t>(rows));
  for (std::size_t k = 0; k < p.seams.size(); ++k) {
    // The seam lies on a polygon corner: it is folded like the creases between strips.
    EXPECT_NEAR(measured_seam_fold_angle(p, static_cast<int>(k)), -2 * kPi / facets, 1e-12);
  }
  for (int n : {1, 2}) {
    const SegmentMesh mesh = subdivide_pattern(p, n);
    const int around = facets * n, along = rows * n;
    ASSERT_EQ(mesh.cells.size(), static_cast<std::size_t>(around * along));
    // Closed around: every cell has two neighbours around and one or two along.
    EXPECT_EQ(mesh.links.size(), static_cast<std::size_t>(around * along + around * (along - 1)));
    std::vector<int> count(mesh.cells.size(), 0);
    int seam_links = 0;
    for (const CellLink& l : mesh.links) {
      ++count[l.left];
      ++count[l.right];
      if (l.seam >= 0) {
        ++seam_links;
        // The two copies of the side coincide when folded, a with a_right, b with b_right.
        EXPECT_LT((mesh.folded_m[l.a] - mesh.folded_m[l.a_right]).norm(), 1e-15);
        EXPECT_LT((mesh.folded_m[l.b] - mesh.folded_m[l.b_right]).norm(), 1e-15);
        EXPECT_NE(l.a, l.a_right);
      } else {
        EXPECT_EQ(l.a, l.a_right);
        EXPECT_EQ(l.b, l.b_right);
      }
    }
    EXPECT_EQ(seam_links, along);
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
      const int i = static_cast<int>(c) / n % n + (static_cast<int>(c) / (n * n * facets)) * n;
      const bool end = i == 0 || i == along - 1;
      EXPECT_EQ(count[c], end ? 3 : 4) << "cell " << c;
    }
    // The folded ring is at rest: every element, seams included, carries no force.
    const Model m = build_pattern_model(p, tube_spec(n, facets));
    ASSERT_EQ(m.elements.size(), mesh.links.size());
    BodyForces f;
    compute_forces(m, initial_state(m), f);
    const double scale = 1e9 * 1e-3 * 0.2;  // E t L: a force of unit strain, N
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      EXPECT_LT(f.f_W[b].norm(), 1e-12 * scale) << b;
      EXPECT_LT(f.tau_W[b].norm(), 1e-12 * scale * 0.05) << b;
    }
  }
}

// Faces 0 (clamped), 1 and 2 in a row; `cut`: face 2 lies apart on the flat sheet and a seam
// joins it to face 1, its folded coordinates put it back in line.
CreasePattern strip(bool cut) {
  CreasePattern p;
  p.vertices_flat_m = {{-0.02, 0},  {0, 0},      {0.1, 0},  {0.2, 0},
                       {0.2, 0.06}, {0.1, 0.06}, {0, 0.06}, {-0.02, 0.06}};
  p.faces = {{0, 1, 6, 7}, {1, 2, 5, 6}, {2, 3, 4, 5}};
  if (cut) {
    for (const Vec2& v : p.vertices_flat_m) p.vertices_folded_m.emplace_back(v.x(), v.y(), 0);
    const Vec2 shift(0.5, 0.3);
    p.vertices_flat_m.push_back(p.vertices_flat_m[2] + shift);  // 8: face 2's copy of 2
    p.vertices_flat_m.push_back(p.vertices_flat_m[5] + shift);  // 9: face 2's copy of 5
    p.vertices_folded_m.push_back(p.vertices_folded_m[2]);
    p.vertices_folded_m.push_back(p.vertices_folded_m[5]);
    for (int v : {3, 4}) p.vertices_flat_m[v] += shift;
    p.faces[2] = {8, 3, 4, 9};
  }
  p.edges = edges_from_faces(p.faces);
  for (PatternEdge& e : p.edges) {
    if (e.assignment == EdgeAssignment::Flat) e.assignment = EdgeAssignment::Join;
  }
  derive_edge_faces(p, "<strip>");
  if (cut) {
    // Face 2's edge 9-8 and face 1's edge 2-5, in this order: the seam's element then sits
    // on face 1 as the uncut sheet's does (it carries its frame on the left of edge b).
    int a = -1, b = -1;
    for (std::size_t e = 0; e < p.edges.size(); ++e) {
      const auto v = p.edges[e].vertices;
      if ((v[0] == 2 && v[1] == 5) || (v[0] == 5 && v[1] == 2)) a = static_cast<int>(e);
      if ((v[0] == 8 && v[1] == 9) || (v[0] == 9 && v[1] == 8)) b = static_cast<int>(e);
    }
    p.seams = {{b, a}};
  }
  return p;
}

std::vector<Vec3> bent_and_twisted(bool cut) {
  CreasePattern p = strip(cut);
  validate_pattern(p, "<strip>");
  PatternSheetSpec spec;
  spec.thickness = 1e-3;
  spec.youngs_modulus = 1e9;
  spec.subdivisions = 3;
  spec.fixed_faces = {0};
  Model m = build_pattern_model(p, spec);
  // A corner load at the free end: bending, twist and in-plane shear together.
  LoadDef load;
  load.body = static_cast<int>(m.bodies.size()) - 1;
  load.force = Vec3(0.5, 0.2, -0.05);
  m.loads = {load};
  State s = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Static;
  set.tolerance = 1e-12;  // the comparison's 1e-9 must not measure the solver's stopping point
  const SolverStats st = run_solver(m, s, set, nullptr);
  EXPECT_EQ(st.status, "ok") << st.message;
  std::vector<Vec3> u;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) u.push_back(s.p_W[b] - m.bodies[b].p0_W);
  return u;
}

TEST(PatternSeams, APlateCutAndSeamedIsTheUncutPlate) {
  const std::vector<Vec3> whole = bent_and_twisted(false), seamed = bent_and_twisted(true);
  ASSERT_EQ(whole.size(), seamed.size());
  double largest = 0;
  for (const Vec3& u : whole) largest = std::max(largest, u.norm());
  ASSERT_GT(largest, 1e-4);
  for (std::size_t b = 0; b < whole.size(); ++b) {
    EXPECT_LT((whole[b] - seamed[b]).norm(), 1e-9 * largest) << "body " << b;
  }
}

TEST(PatternSeams, FoldFileRoundTripKeepsTheSeams) {
  const CreasePattern p = tube_crease_pattern(5, 2, 0.03, 0.1);
  const std::string text = fold_text(p);
  EXPECT_NE(text.find("\"finseg:seams\""), std::string::npos);
  const CreasePattern q = parse_fold(text, "tube.fold");
  EXPECT_EQ(q.seams, p.seams);
  EXPECT_EQ(fold_text(q), text);
}

TEST(PatternSeams, BadSeamsAreRefused) {
  const test::TempDir dir;
  auto with = [](nlohmann::json seams) {
    nlohmann::json f = test::two_squares();
    f["finseg:seams"] = std::move(seams);
    return f;
  };
  using nlohmann::json;
  test::expect_refused(dir, with(3), "finseg:seams", "must be an array");
  test::expect_refused(dir, with(json::parse("[[0]]")), "finseg:seams[0]", "pair");
  test::expect_refused(dir, with(json::parse("[[0, -1]]")), "finseg:seams[0]", "not an edge index");
  test::expect_refused(dir, with(json::parse("[[0, 99]]")), "finseg:seams[0]",
                       "edge 99 out of range");
  test::expect_refused(dir, with(json::parse("[[0, 6]]")), "finseg:seams[0]", "'V'");
  test::expect_refused(dir, with(json::parse("[[2, 2]]")), "finseg:seams[0]", "joined to itself");
  test::expect_refused(dir, with(json::parse("[[2, 5], [5, 0]]")), "finseg:seams[1]",
                       "edge 5 is in seam 0 already");
  json longer = with(json::parse("[[0, 1]]"));
  longer["vertices_coords"][2] = {2.5, 0};
  longer["vertices_coords"][3] = {2.5, 1};
  test::expect_refused(dir, longer, "finseg:seams[0]", "equal length");
  json turned = with(json::parse("[[2, 5]]"));
  turned["edges_vertices"][5] = {0, 5};
  test::expect_refused(dir, turned, "finseg:seams[0]", "Moebius");
  // Folded flat as drawn, the seam's ends lie 2 mm apart.
  json apart = with(json::parse("[[2, 5]]"));
  apart.erase("edges_foldAngle");
  apart["edges_assignment"][6] = "F";
  json folded = {{"frame_classes", {"foldedForm"}}, {"vertices_coords", json::array()}};
  for (const json& v : apart["vertices_coords"])
    folded["vertices_coords"].push_back({v[0], v[1], 0});
  apart["file_frames"] = {folded};
  test::expect_refused(dir, apart, "finseg:seams[0]", "lies 0.002 m from vertex 0");
  // Valid on the flat sheet, but a seam cannot start flat: its edges lie apart there.
  nlohmann::json fine = with(json::parse("[[2, 5]]"));
  fine.erase("edges_foldAngle");
  fine["edges_assignment"][6] = "F";
  const CreasePattern p = parse_fold(fine.dump(), "fine.fold");
  try {
    build_pattern_model(p, PatternSheetSpec{}, "fine.fold");
    ADD_FAILURE() << "a seam started flat";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "finseg:seams");
    EXPECT_NE(std::string(e.what()).find("folded"), std::string::npos) << e.what();
  }
}

}  // namespace pattern_seams_test
}  // namespace finseg
