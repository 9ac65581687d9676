#include "patterns/flat_tube_pattern.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "core/error.hpp"
#include "patterns/pattern_checks.hpp"

namespace finseg {

namespace {

void check_spec(const FlatTubeSpec& s) {
  auto refuse = [](const char* field, const std::string& why) {
    throw InputError("<api>", field, why);
  };
  if (s.layer_facets < 2 || s.layer_facets > 256) {
    refuse("layer_facets", fmt::format("{}; allowed 2..256", s.layer_facets));
  }
  if (s.rows < 3 || s.rows > 10000) refuse("rows", fmt::format("{}; allowed 3..10000", s.rows));
  if (!(s.width > 0 && std::isfinite(s.width))) {
    refuse("width", fmt::format("{} m; must be > 0", s.width));
  }
  if (!(s.gap > 0 && s.gap < s.width / s.layer_facets)) {
    refuse("gap", fmt::format("{} m; allowed (0, width / layer_facets = {} m)", s.gap,
                              s.width / s.layer_facets));
  }
  if (!(s.length > 0 && std::isfinite(s.length))) {
    refuse("length", fmt::format("{} m; must be > 0", s.length));
  }
  if (!(s.seal_length > 0 && 2 * s.seal_length < s.length)) {
    refuse("seal_length",
           fmt::format("{} m; allowed (0, length / 2 = {} m)", s.seal_length, s.length / 2));
  }
}

// Makes a face counter-clockwise in the flat coordinates.
std::vector<int> ccw(const CreasePattern& p, std::vector<int> f) {
  double area2 = 0;
  for (std::size_t a = 0; a < f.size(); ++a) {
    const Vec2 &u = p.vertices_flat_m[f[a]], &v = p.vertices_flat_m[f[(a + 1) % f.size()]];
    area2 += u.x() * v.y() - u.y() * v.x();
  }
  if (area2 < 0) std::reverse(f.begin(), f.end());
  return f;
}

}  // namespace

CreasePattern flat_tube_crease_pattern(const FlatTubeSpec& s) {
  check_spec(s);
  const int k = s.layer_facets, N = 2 * k + 2, R = s.rows;
  const double W = s.width, h = s.gap, w = W / k, dy = (s.length - 2 * s.seal_length) / (R - 2);
  // A seal row's development length: its layers fall by gap / 2 over seal_length.
  const double seal = std::sqrt(s.seal_length * s.seal_length + h * h / 4);
  CreasePattern p;
  p.meta.file_creator = "finseg";
  p.meta.frame_title = fmt::format("lay-flat tube of {} + {} facets x {} rows", k, k, R);
  // Section corners around the tube from the top-left one: the top layer (+x), the right
  // gusset, the bottom layer (-x), the left gusset; corner q's column (q to q + 1) is a
  // gusset for q = k and 2 k + 1, else a facet. The development starts at corner `first`,
  // the middle of the bottom layer, so that the seam along the tube is a flat joint between
  // two bottom facets rather than one of the section's corners.
  auto corner = [&](int q) {
    q %= N;
    return q <= k           ? Vec2(-W / 2 + q * w, h / 2)
           : q <= 2 * k + 1 ? Vec2(W / 2 - (q - k - 1) * w, -h / 2)
                            : Vec2(-W / 2, h / 2);  // not reached: q < N
  };
  const int first = k + 1 + k / 2;
  auto is_gusset = [&](int c) {  // development column c
    const int q = (c + first) % N;
    return q == k || q == 2 * k + 1;
  };
  std::vector<double> X(N + 1, 0.0);
  std::vector<Vec2> xz(N + 1);
  for (int j = 0; j <= N; ++j) {
    xz[j] = corner(j + first);
    if (j > 0) X[j] = X[j - 1] + (is_gusset(j - 1) ? h : w);
  }
  // Development column of corner column q.
  auto column = [&](int q) { return ((q - first) % N + N) % N; };
  auto Y = [&](int i) {
    return i == 0 ? 0.0 : i == R ? 2 * seal + (R - 2) * dy : seal + (i - 1) * dy;
  };
  auto y_axial = [&](int i) {
    return i == 0 ? 0.0 : i == R ? s.length : s.seal_length + (i - 1) * dy;
  };
  auto id = [&](int i, int j) { return i * (N + 1) + j; };
  for (int i = 0; i <= R; ++i) {
    const bool end = i == 0 || i == R;  // the seal line: both layers at z = 0
    for (int j = 0; j <= N; ++j) {
      p.vertices_flat_m.emplace_back(X[j], Y(i));
      p.vertices_folded_m.emplace_back(xz[j].x(), y_axial(i), end ? 0.0 : xz[j].y());
    }
  }
  // The gussets' columns (between lines a and a + 1) and their end-edge middles M.
  const std::array<int, 2> gusset{column(k), column(2 * k + 1)};
  std::map<std::pair<int, int>, int> middle;  // (end row line, gusset column) -> vertex
  for (int i : {0, R}) {
    for (int a : gusset) {
      middle[{i, a}] = static_cast<int>(p.vertices_flat_m.size());
      p.vertices_flat_m.emplace_back((X[a] + X[a + 1]) / 2, Y(i));
      const double out = a == gusset[0] ? W / 2 + h / 2 : -W / 2 - h / 2;
      p.vertices_folded_m.emplace_back(out, y_axial(i), 0.0);
    }
  }
  for (int r = 0; r < R; ++r) {
    const bool seal_row = r == 0 || r == R - 1;
    const int end = r == 0 ? 0 : R, in = r == 0 ? 1 : R - 1;
    for (int c = 0; c < N; ++c) {
      if (seal_row && (c == gusset[0] || c == gusset[1])) {
        const int m = middle[{end, c}];
        p.faces.push_back(ccw(p, {id(in, c), id(in, c + 1), m}));
        p.faces.push_back(ccw(p, {id(in, c), m, id(end, c)}));
        p.faces.push_back(ccw(p, {id(in, c + 1), id(end, c + 1), m}));
      } else {
        p.faces.push_back({id(r, c), id(r, c + 1), id(r + 1, c + 1), id(r + 1, c)});
      }
    }
  }
  p.edges = edges_from_faces(p.faces);
  derive_edge_faces(p, "<flat tube>");
  std::map<std::pair<int, int>, int> edge_of;
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    const auto [u, v] = p.edges[e].vertices;
    edge_of[{std::min(u, v), std::max(u, v)}] = static_cast<int>(e);
  }
  auto edge = [&](int u, int v) { return edge_of.at({std::min(u, v), std::max(u, v)}); };
  const int grid = (R + 1) * (N + 1);
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    PatternEdge& ed = p.edges[e];
    if (ed.face_count() != 2) continue;
    const auto [u, v] = ed.vertices;
    const bool on_grid = u < grid && v < grid;
    const int row = u / (N + 1);
    if (on_grid && row == v / (N + 1) && row >= 2 && row <= R - 2) {
      ed.assignment = EdgeAssignment::Join;  // a row line of the straight part
      continue;
    }
    const double angle = measured_fold_angle(p, static_cast<int>(e));
    ed.fold_angle = std::abs(angle) < 1e-12 ? 0.0 : angle;
    if (on_grid && u % (N + 1) == v % (N + 1)) {
      ed.assignment = EdgeAssignment::Mountain;  // a column line: a corner of the section
    } else {
      ed.assignment = ed.fold_angle > 0   ? EdgeAssignment::Valley
                      : ed.fold_angle < 0 ? EdgeAssignment::Mountain
                                          : EdgeAssignment::Flat;
    }
  }
  // Along the tube: column N's free edge onto column 0's. At each end: a layer's end edge onto
  // the other layer's facet above it, a gusset's half end edge onto its other half.
  for (int i = 0; i < R; ++i)
    p.seams.push_back({edge(id(i, 0), id(i + 1, 0)), edge(id(i, N), id(i + 1, N))});
  for (int i : {0, R}) {
    for (int j = 0; j < k; ++j) {  // top facet j over bottom facet k - 1 - j
      const int top = column(j), bottom = column(2 * k - j);
      p.seams.push_back({edge(id(i, top), id(i, top + 1)), edge(id(i, bottom), id(i, bottom + 1))});
    }
    for (int a : gusset) {
      const int m = middle[{i, a}];
      p.seams.push_back({edge(id(i, a), m), edge(m, id(i, a + 1))});
    }
  }
  p.has_fold_angles = true;
  return p;
}

std::vector<int> flat_tube_row_faces(const FlatTubeSpec& s, int row) {
  const int N = 2 * s.layer_facets + 2, seal = N + 4;  // a seal row: 2 gussets x 3 triangles
  if (row < 0 || row >= s.rows)
    throw InputError("<api>", "row", fmt::format("{}; allowed 0..{}", row, s.rows - 1));
  const int first = row == 0 ? 0 : seal + (row - 1) * N;
  const int count = row == 0 || row == s.rows - 1 ? seal : N;
  std::vector<int> faces(count);
  for (int f = 0; f < count; ++f) faces[f] = first + f;
  return faces;
}

double flat_tube_volume(const FlatTubeSpec& s) {
  const double straight = s.length - 2 * s.seal_length;
  return s.gap * (s.width * straight + 2 * s.seal_length * (s.width / 2 + s.gap / 6));
}

double flat_tube_round_area(const FlatTubeSpec& s) {
  const int k = s.layer_facets;
  const double w = s.width / k, h = s.gap;
  // Circumradius rho: the sides' central angles 2 asin(side / (2 rho)) add up to 2 pi (the
  // centre inside: every side shorter than the rest together). Decreasing in rho: bisection.
  auto excess = [&](double rho) {
    return 2 * k * std::asin(w / (2 * rho)) + 2 * std::asin(h / (2 * rho)) - kPi;
  };
  double lo = w / 2, hi = k * w + h;  // excess(lo) >= 0 for k >= 2; excess(hi) < 0
  for (int it = 0; it < 200; ++it) {
    const double mid = (lo + hi) / 2;
    (excess(mid) > 0 ? lo : hi) = mid;
  }
  const double rho = (lo + hi) / 2;
  auto triangle = [&](double side) {
    return rho * rho * std::sin(2 * std::asin(side / (2 * rho))) / 2;
  };
  return 2 * k * triangle(w) + 2 * triangle(h);
}

}  // namespace finseg
