#include "patterns/tube_pattern.hpp"

#include <fmt/format.h>

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

}  // namespace finseg
