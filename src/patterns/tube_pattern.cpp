#include "patterns/tube_pattern.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace finseg {

CreasePattern tube_crease_pattern(int facets, int rows, double radius, double length) {
  if (facets < 3 || rows < 1 || !(radius > 0) || !(length > 0)) {
    throw InputError("<api>", "tube",
                     fmt::format("{} facets, {} rows, radius {} m, length {} m; need >= 3, >= 1, "
                                 "> 0, > 0",
                                 facets, rows, radius, length));
  }
  const int n = facets;
  const double a = 2 * radius * std::sin(kPi / n), dy = length / rows;
  CreasePattern p;
  p.meta.file_creator = "finseg";
  p.meta.frame_title = fmt::format("tube of {} facets x {} rows", n, rows);
  auto id = [&](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i <= rows; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double theta = 2 * kPi * j / n;
      p.vertices_flat_m.emplace_back(j * a, i * dy);
      // x_flat -> the tangent (-sin, 0, -cos), y_flat -> +y: the flat +z maps to the
      // outward normal (cos, 0, -sin).
      p.vertices_folded_m.emplace_back(radius * std::cos(theta), i * dy, -radius * std::sin(theta));
    }
  }
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < n; ++j) {
      p.faces.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
    }
  }
  // Edges oriented by their first face (left of u -> v), so both seam edges have their face
  // on the left: column 0 runs down, column n up, and a.u = (i + 1, 0) meets b.v = (i + 1, n).
  p.edges = edges_from_faces(p.faces);
  std::vector<int> first(rows, -1), last(rows, -1);
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    PatternEdge& edge = p.edges[e];
    const int u = edge.vertices[0], v = edge.vertices[1];
    const int ju = u % (n + 1), jv = v % (n + 1), iu = u / (n + 1), iv = v / (n + 1);
    if (ju != jv) {  // along a row line
      if (edge.assignment == EdgeAssignment::Flat) edge.assignment = EdgeAssignment::Join;
    } else if (ju == 0) {
      first[std::min(iu, iv)] = static_cast<int>(e);
    } else if (ju == n) {
      last[std::min(iu, iv)] = static_cast<int>(e);
    } else {
      edge.assignment = EdgeAssignment::Mountain;
      edge.fold_angle = -2 * kPi / n;
    }
  }
  for (int i = 0; i < rows; ++i) p.seams.push_back({first[i], last[i]});
  p.has_fold_angles = true;
  derive_edge_faces(p, "<tube>");
  return p;
}

namespace {

// Closes both ends of a tube from tube_crease_pattern by a regular N-gon cap each, laid apart
// on the flat sheet (beside the strip) and glued to the end row's edges by seams: where the
// folded sheet turns through the right angle there, the seams become mountain creases.
// Caps are counter-clockwise on the flat sheet and their flat +z faces out of the tube.
void close_tube_ends(CreasePattern& p, int n, int rows, double radius, double length) {
  auto id = [&](int i, int j) { return i * (n + 1) + j; };
  auto edge_of = [&](int u, int v) {
    for (std::size_t e = 0; e < p.edges.size(); ++e) {
      if (p.edges[e].vertices[0] == u && p.edges[e].vertices[1] == v) return static_cast<int>(e);
    }
    throw InputError("<tube>", "edges", fmt::format("no edge {} -> {}", u, v));
  };
  const double width = n * 2 * radius * std::sin(kPi / n);
  for (const bool top : {false, true}) {
    const int i = top ? rows : 0, first = static_cast<int>(p.vertices_flat_m.size());
    // Flat: beside the strip, clear of it; bottom cap counter-clockwise in -theta.
    const Vec2 centre(width + 2 * radius, top ? length - radius : radius);
    std::vector<int> loop;
    for (int k = 0; k < n; ++k) {
      const double theta = 2 * kPi * k / n, s = top ? 1 : -1;
      p.vertices_flat_m.push_back(centre + radius * Vec2(std::cos(s * theta), std::sin(s * theta)));
      p.vertices_folded_m.push_back(p.vertices_folded_m[id(i, k)]);
      loop.push_back(first + k);
    }
    if (!top) std::reverse(loop.begin(), loop.end());
    p.faces.push_back(loop);
    for (int k = 0; k < n; ++k) {
      // Top: the tube runs (k + 1) -> k, the cap k -> k + 1; bottom the other way round.
      const int a = first + k, b = first + (k + 1) % n;
      PatternEdge cap;
      cap.assignment = EdgeAssignment::Boundary;
      cap.vertices = top ? std::array<int, 2>{a, b} : std::array<int, 2>{b, a};
      p.edges.push_back(cap);
      const int tube = top ? edge_of(id(i, k + 1), id(i, k)) : edge_of(id(i, k), id(i, k + 1));
      p.seams.push_back({tube, static_cast<int>(p.edges.size()) - 1});
    }
  }
}

}  // namespace

CreasePattern zfolded_tube_crease_pattern(int facets, int rows, double radius, double length,
                                          double fold_angle) {
  if (rows < 2 || !(std::abs(fold_angle) <= kPi)) {
    throw InputError("<api>", "tube",
                     fmt::format("{} rows, fold angle {} rad; a zigzag needs >= 2 rows and a "
                                 "fold angle in [-pi, pi]",
                                 rows, fold_angle));
  }
  CreasePattern p = tube_crease_pattern(facets, rows, radius, length);
  const int n = facets;
  p.meta.frame_title = fmt::format("{} tube of {} facets x {} rows",
                                   fold_angle == 0 ? "capped" : "Z-folded", n, rows);
  for (PatternEdge& edge : p.edges) {
    const int u = edge.vertices[0], v = edge.vertices[1];
    const int i = u / (n + 1);
    if (edge.assignment != EdgeAssignment::Join || i == 0 || i == rows) continue;
    const int j = std::min(u % (n + 1), v % (n + 1));
    const double phi = 2 * kPi * (j + 0.5) / n;
    const double c = std::cos(phi), a = (i % 2 == 0 ? 1 : -1) * fold_angle * c;
    // cos(phi) = 0 only up to round-off: those facets lie in the bend's plane.
    edge.fold_angle = std::abs(c) < 1e-12 ? 0.0 : a;
    edge.assignment = edge.fold_angle > 0   ? EdgeAssignment::Valley
                      : edge.fold_angle < 0 ? EdgeAssignment::Mountain
                                            : EdgeAssignment::Flat;
  }
  close_tube_ends(p, n, rows, radius, length);
  derive_edge_faces(p, "<tube>");
  return p;
}

}  // namespace finseg
