#include "patterns/zigzag_pattern.hpp"

#include <fmt/format.h>

#include "core/so3.hpp"

namespace finseg {
namespace {

PatternEdge edge(int a, int b, EdgeAssignment kind, double angle = 0) {
  PatternEdge e;
  e.vertices = {a, b};
  e.assignment = kind;
  e.fold_angle = angle;
  return e;
}

}  // namespace

CreasePattern zigzag_crease_pattern(const ZigzagSpec& spec) {
  const SheetSpec sheet = zigzag_sheet(spec);  // validates the spec
  const int n = spec.panels;
  const double lp = spec.length / n, w = spec.width;
  CreasePattern p;
  p.meta.file_creator = "finseg";
  p.meta.frame_title = fmt::format("zigzag strip, {} panels", n);
  p.has_fold_angles = true;
  Vec3 crease_W = sheet.origin_W;
  Mat3 R_W = sheet.R_W0;
  for (int k = 0; k <= n; ++k) {
    // Vertices 2k (y = 0) and 2k + 1 (y = width) on crease line k (the ends included).
    p.vertices_flat_m.emplace_back(k * lp, 0);
    p.vertices_flat_m.emplace_back(k * lp, w);
    p.vertices_folded_m.push_back(crease_W);
    p.vertices_folded_m.push_back(crease_W + R_W * Vec3(0, w, 0));
    if (k == n) break;
    p.faces.push_back({2 * k, 2 * k + 2, 2 * k + 3, 2 * k + 1});
    crease_W += R_W * Vec3(lp, 0, 0);
    if (k + 1 < n) R_W = R_W * so3_exp<double>(Vec3(0, sheet.folds[k].angle, 0));
  }
  for (int k = 0; k < n; ++k) {
    p.edges.push_back(edge(2 * k, 2 * k + 2, EdgeAssignment::Boundary));
    p.edges.push_back(edge(2 * k + 3, 2 * k + 1, EdgeAssignment::Boundary));
  }
  p.edges.push_back(edge(1, 0, EdgeAssignment::Boundary));
  p.edges.push_back(edge(2 * n, 2 * n + 1, EdgeAssignment::Boundary));
  for (int k = 0; k + 1 < n; ++k) {
    // The sheet's fold angle turns the next panel about +y (down for a peak); FOLD's is
    // positive for a valley seen from +z of the flat pattern: the opposite sign.
    const double fold = -sheet.folds[k].angle;
    p.edges.push_back(edge(2 * k + 2, 2 * k + 3,
                           fold < 0 ? EdgeAssignment::Mountain : EdgeAssignment::Valley, fold));
  }
  derive_edge_faces(p, "<zigzag>");
  return p;
}

}  // namespace finseg
