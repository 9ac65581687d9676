// FOLD crease patterns that must be accepted: round trip, a hand-made Miura-ori sheet, the
// fold-angle sign convention on a hand-folded pair of squares, and the crossing search on a
// large grid against brute force.
#include <cmath>
#include <numeric>

#include "pattern_test_util.hpp"
#include "patterns/grid_pattern.hpp"
#include "patterns/pattern_checks.hpp"
#include "patterns/zigzag_pattern.hpp"

namespace finseg::test {
namespace fold_patterns_test {

using nlohmann::json;

PatternEdge make_edge(int a, int b, EdgeAssignment kind) {
  PatternEdge e;
  e.vertices = {a, b};
  e.assignment = kind;
  return e;
}

// Miura-ori, written out here: rows of parallelograms, vertex (i, j) at
// (j w + (i odd ? t : 0), i h). The straight row lines alternate M/V segment by segment;
// each zigzag column line is all M (odd j) or all V (even j).
CreasePattern miura(int rows, int cols, double w, double h, double t) {
  CreasePattern p;
  p.meta.file_creator = "hand";
  auto id = [&](int i, int j) { return i * (cols + 1) + j; };
  for (int i = 0; i <= rows; ++i) {
    for (int j = 0; j <= cols; ++j) p.vertices_flat_m.emplace_back(j * w + (i % 2) * t, i * h);
  }
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < cols; ++j)
      p.faces.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
  }
  const auto column = [](int j) {
    return j % 2 ? EdgeAssignment::Mountain : EdgeAssignment::Valley;
  };
  const auto other = [](EdgeAssignment a) {
    return a == EdgeAssignment::Mountain ? EdgeAssignment::Valley : EdgeAssignment::Mountain;
  };
  for (int i = 0; i <= rows; ++i) {
    for (int j = 0; j < cols; ++j) {
      const bool border = i == 0 || i == rows;
      p.edges.push_back(
          make_edge(id(i, j), id(i, j + 1),
                    border ? EdgeAssignment::Boundary : (i % 2 ? column(j) : other(column(j)))));
    }
  }
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j <= cols; ++j) {
      p.edges.push_back(make_edge(id(i, j), id(i + 1, j),
                                  j == 0 || j == cols ? EdgeAssignment::Boundary : column(j)));
    }
  }
  return p;
}

void expect_same(const CreasePattern& a, const CreasePattern& b) {
  ASSERT_EQ(a.vertices_flat_m.size(), b.vertices_flat_m.size());
  for (std::size_t i = 0; i < a.vertices_flat_m.size(); ++i) {
    EXPECT_EQ(a.vertices_flat_m[i], b.vertices_flat_m[i]) << i;
  }
  ASSERT_EQ(a.vertices_folded_m.size(), b.vertices_folded_m.size());
  for (std::size_t i = 0; i < a.vertices_folded_m.size(); ++i) {
    EXPECT_EQ(a.vertices_folded_m[i], b.vertices_folded_m[i]) << i;
  }
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.has_fold_angles, b.has_fold_angles);
  ASSERT_EQ(a.edges.size(), b.edges.size());
  for (std::size_t e = 0; e < a.edges.size(); ++e) {
    EXPECT_EQ(a.edges[e].vertices, b.edges[e].vertices);
    EXPECT_EQ(a.edges[e].assignment, b.edges[e].assignment);
    EXPECT_EQ(a.edges[e].faces, b.edges[e].faces);
    // rad -> deg -> rad: at most a few ulps.
    EXPECT_NEAR(a.edges[e].fold_angle, b.edges[e].fold_angle, 1e-15);
  }
  EXPECT_EQ(a.meta.file_creator, b.meta.file_creator);
  EXPECT_EQ(a.meta.frame_title, b.meta.frame_title);
}

TEST(FoldPatterns, RoundTripWithFoldedFrameAndWithout) {
  TempDir dir;
  ZigzagSpec z;
  z.panels = 7;
  z.pattern = "PPVPVV";
  const CreasePattern strip = zigzag_crease_pattern(z);
  write_fold(dir / "strip.fold", strip);
  const CreasePattern back = read_fold(dir / "strip.fold");
  expect_same(strip, back);
  EXPECT_EQ(back.meta.file_spec, 1.1);
  // Deterministic: the same pattern gives the same bytes, also after a round trip.
  EXPECT_EQ(fold_text(strip), slurp(dir / "strip.fold"));
  EXPECT_EQ(fold_text(back), fold_text(strip));

  CreasePattern m = miura(3, 4, 0.02, 0.015, 0.006);
  m.edges[7].assignment = EdgeAssignment::Join;  // an interior edge: FOLD 1.2
  write_fold(dir / "miura.fold", m);
  EXPECT_NE(slurp(dir / "miura.fold").find("\"file_spec\": 1.2"), std::string::npos);
  const CreasePattern mb = read_fold(dir / "miura.fold");
  validate_pattern(m, "<test>");  // fills m's edge faces for the comparison
  expect_same(m, mb);
}

TEST(FoldPatterns, MiuraSheetIsAccepted) {
  const int rows = 4, cols = 5;
  CreasePattern m = miura(rows, cols, 0.02, 0.015, 0.006);
  EXPECT_NO_THROW(validate_pattern(m, "<miura>"));
  EXPECT_EQ(m.vertices_flat_m.size(), static_cast<std::size_t>((rows + 1) * (cols + 1)));
  int creases = 0, boundary = 0;
  for (const PatternEdge& e : m.edges) {
    creases += is_crease(e.assignment);
    boundary += e.assignment == EdgeAssignment::Boundary;
    EXPECT_EQ(e.face_count(), e.assignment == EdgeAssignment::Boundary ? 1 : 2);
  }
  EXPECT_EQ(boundary, 2 * (rows + cols));
  EXPECT_EQ(creases, (rows - 1) * cols + rows * (cols - 1));
  // Maekawa at every interior vertex (a check of the hand-written assignment itself).
  std::vector<int> mountains(m.vertices_flat_m.size()), valleys(m.vertices_flat_m.size());
  for (const PatternEdge& e : m.edges) {
    for (int v : e.vertices) {
      mountains[v] += e.assignment == EdgeAssignment::Mountain;
      valleys[v] += e.assignment == EdgeAssignment::Valley;
    }
  }
  for (int i = 1; i < rows; ++i) {
    for (int j = 1; j < cols; ++j) {
      const int v = i * (cols + 1) + j;
      EXPECT_EQ(std::abs(mountains[v] - valleys[v]), 2) << "vertex " << v;
    }
  }
  // Written without edges, the faces alone give the same boundary and F edges elsewhere.
  json bare = {
      {"frame_unit", "m"}, {"vertices_coords", json::array()}, {"faces_vertices", m.faces}};
  for (const Vec2& v : m.vertices_flat_m) bare["vertices_coords"].push_back({v.x(), v.y()});
  const CreasePattern derived = parse_fold(bare.dump(), "<bare>");
  EXPECT_EQ(derived.edges.size(), m.edges.size());
  int flat = 0;
  for (const PatternEdge& e : derived.edges) flat += e.assignment == EdgeAssignment::Flat;
  EXPECT_EQ(flat, creases);
}

TEST(FoldPatterns, FoldAngleSignFromHandFoldedSquares) {
  // Face 1 turned up 90 degrees about the crease 1 -> 4: the normals (+z of the flat
  // pattern) turn towards each other, a valley: +90 degrees in FOLD's convention.
  json f = two_squares();
  const json up = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}, {0, 1, 0}};
  const json down = {{0, 0, 0}, {1, 0, 0}, {1, 0, -1}, {1, 1, -1}, {1, 1, 0}, {0, 1, 0}};
  f["file_frames"] = {{{"frame_classes", {"foldedForm"}}, {"vertices_coords", up}}};
  EXPECT_NEAR(measured_fold_angle(parse_fold(f.dump(), "<up>"), 6), kPi / 2, 1e-12);
  f["file_frames"][0]["vertices_coords"] = down;
  f["edges_assignment"][6] = "M";
  f["edges_foldAngle"][6] = -90;
  const CreasePattern p = parse_fold(f.dump(), "<down>");
  EXPECT_NEAR(measured_fold_angle(p, 6), -kPi / 2, 1e-12);
  EXPECT_NEAR(p.vertices_folded_m[2].z(), -1e-3, 1e-18);  // inherits frame_unit mm
}

// Independent reference: do segments ab and cd cross (general position, no shared ends)?
bool crosses(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  Eigen::Matrix2d m;
  m << b - a, c - d;
  if (std::abs(m.determinant()) < 1e-300) return false;
  const Vec2 st = m.inverse() * (c - a);
  return st.x() >= 0 && st.x() <= 1 && st.y() >= 0 && st.y() <= 1;
}

TEST(FoldPatterns, CrossingSearchMatchesBruteForce) {
  // 250 segments with quasi-random ends (golden-ratio sequences): many crossings.
  std::vector<Vec2> xy;
  std::vector<PatternEdge> edges;
  const double g1 = 0.6180339887498949, g2 = 0.7548776662466927, g3 = 0.5698402909980532;
  for (int i = 0; i < 250; ++i) {
    const Vec2 a(std::fmod(i * g1, 1.0) * 4, std::fmod(i * g2, 1.0) * 4);
    const double ang = std::fmod(i * g3, 1.0) * 2 * kPi, len = 0.05 + std::fmod(i * g1 * g2, 1.0);
    xy.push_back(a);
    xy.push_back(a + len * Vec2(std::cos(ang), std::sin(ang)));
    edges.push_back(make_edge(2 * i, 2 * i + 1, EdgeAssignment::Boundary));
  }
  // Find the first crossing, drop its second edge, repeat until none is left: every answer
  // on the way must be the brute force's.
  std::vector<int> alive(250);
  std::iota(alive.begin(), alive.end(), 0);
  int found = 0;
  for (;;) {
    std::vector<PatternEdge> sub;
    for (int i : alive) sub.push_back(edges[i]);
    std::optional<std::array<int, 2>> expected;
    for (std::size_t i = 0; i < sub.size() && !expected; ++i) {
      for (std::size_t j = i + 1; j < sub.size() && !expected; ++j) {
        const auto &u = sub[i].vertices, &v = sub[j].vertices;
        if (crosses(xy[u[0]], xy[u[1]], xy[v[0]], xy[v[1]])) {
          expected = std::array<int, 2>{static_cast<int>(i), static_cast<int>(j)};
        }
      }
    }
    ASSERT_EQ(find_edge_crossing(xy, sub, 1e-12), expected) << sub.size() << " edges";
    if (!expected) break;
    alive.erase(alive.begin() + (*expected)[1]);
    ++found;
  }
  EXPECT_GE(found, 100);  // the construction does cross, many times
}

TEST(FoldPatterns, LargeGridValidatesAndFindsOneAddedCrossing) {
  const int n = 300;
  CreasePattern p = grid_crease_pattern(n, n, 1.0, 1.0);
  ASSERT_EQ(p.edges.size(), static_cast<std::size_t>(2 * n * (n + 1)));
  for (const PatternEdge& e : p.edges)
    EXPECT_EQ(e.face_count(), e.assignment == EdgeAssignment::Boundary ? 1 : 2);
  EXPECT_NO_THROW(validate_pattern(p, "<grid>"));
  // A long edge across the sheet: the first edge it meets, by brute force.
  const int a = static_cast<int>(p.vertices_flat_m.size());
  p.vertices_flat_m.emplace_back(0.5, 0.25);
  p.vertices_flat_m.emplace_back(n - 0.5, n - 0.75);
  p.edges.push_back(make_edge(a, a + 1, EdgeAssignment::Boundary));
  const int added = static_cast<int>(p.edges.size()) - 1;
  int first = -1;
  for (int e = 0; e < added && first < 0; ++e) {
    const auto& v = p.edges[e].vertices;
    if (crosses(p.vertices_flat_m[v[0]], p.vertices_flat_m[v[1]], p.vertices_flat_m[a],
                p.vertices_flat_m[a + 1])) {
      first = e;
    }
  }
  ASSERT_GE(first, 0);
  const auto hit = find_edge_crossing(p.vertices_flat_m, p.edges, 1e-9 * n);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ((*hit)[0], first);
  EXPECT_EQ((*hit)[1], added);
}

}  // namespace fold_patterns_test
}  // namespace finseg::test
