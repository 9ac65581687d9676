#include "patterns/sheet_pattern.hpp"

namespace finseg {
namespace {

PatternEdge edge(int a, int b, EdgeAssignment kind, double angle = 0) {
  PatternEdge e;
  e.vertices = {a, b};
  e.assignment = kind;
  e.fold_angle = angle;
  return e;
}

// A line across the flat sheet at x (m): a fold (index into spec.folds), a cell boundary
// inside a panel, or an end of the sheet (or of its clamp column).
struct CutLine {
  double x = 0;
  int panel = 0;  // the panel the line starts (the last panel for the far end)
  int fold = -1;
};

std::vector<CutLine> cut_lines(const SheetSpec& spec, const std::vector<double>& panel_start,
                               bool cells) {
  const int n = static_cast<int>(panel_start.size()) - 1;
  std::vector<CutLine> lines;
  for (int k = 0; k < n; ++k) {
    const double a = panel_start[k], b = panel_start[k + 1];
    const std::vector<double> bounds = panel_cell_bounds(spec, a, b, k > 0, k + 1 < n);
    if (k == 0 && spec.clamp_start) lines.push_back({-0.5 * (bounds[1] - bounds[0]), 0});
    lines.push_back({a, k, k > 0 ? k - 1 : -1});
    if (!cells) continue;
    for (std::size_t j = 1; j + 1 < bounds.size(); ++j) lines.push_back({bounds[j], k});
  }
  lines.push_back({spec.length, n - 1, -1});
  return lines;
}

}  // namespace

SheetPattern sheet_crease_pattern(const SheetSpec& spec, bool cells) {
  const int rows = cells ? spec.cells_across : 1;
  const double w = spec.width;
  const std::vector<double> panel_start = panel_starts(spec);
  const std::vector<PanelFrame> frame = panel_frames(spec);
  const std::vector<CutLine> lines = cut_lines(spec, panel_start, cells);
  const int m = static_cast<int>(lines.size());
  auto vertex = [&](int j, int r) { return j * (rows + 1) + r; };
  SheetPattern out;
  CreasePattern& p = out.pattern;
  p.has_fold_angles = true;
  for (int j = 0; j < m; ++j) {
    const CutLine& l = lines[j];
    const PanelFrame& f = frame[l.panel];
    const Vec3 base_W = f.o_W + f.R_W * Vec3(l.x - panel_start[l.panel], 0, 0);
    for (int r = 0; r <= rows; ++r) {
      const double y = w * r / rows;
      p.vertices_flat_m.emplace_back(l.x, y);
      p.vertices_folded_m.push_back(base_W + f.R_W * Vec3(0, y, 0));
    }
    if (j + 1 == m) break;
    for (int r = 0; r < rows; ++r) {
      p.faces.push_back({vertex(j, r), vertex(j + 1, r), vertex(j + 1, r + 1), vertex(j, r + 1)});
      out.face_panel.push_back(lines[j].panel);
      out.face_clamp.push_back(spec.clamp_start && j == 0);
    }
  }
  // Along the sheet: its two long sides (B) and the cuts between rows (F).
  for (int j = 0; j + 1 < m; ++j) {
    p.edges.push_back(edge(vertex(j, 0), vertex(j + 1, 0), EdgeAssignment::Boundary));
    for (int r = 1; r < rows; ++r) {
      p.edges.push_back(edge(vertex(j, r), vertex(j + 1, r), EdgeAssignment::Flat));
    }
    p.edges.push_back(edge(vertex(j + 1, rows), vertex(j, rows), EdgeAssignment::Boundary));
  }
  for (int r = 0; r < rows; ++r) {
    p.edges.push_back(edge(vertex(0, r + 1), vertex(0, r), EdgeAssignment::Boundary));
  }
  for (int r = 0; r < rows; ++r) {
    p.edges.push_back(edge(vertex(m - 1, r), vertex(m - 1, r + 1), EdgeAssignment::Boundary));
  }
  out.fold_edges.resize(spec.folds.size());
  for (int j = 1; j + 1 < m; ++j) {
    const int f = lines[j].fold;
    // The sheet's fold angle turns the next panel about +y (down for a peak); FOLD's is
    // positive for a valley seen from +z of the flat pattern: the opposite sign.
    const double fold = f < 0 ? 0.0 : -spec.folds[f].angle;
    const EdgeAssignment kind = f < 0      ? EdgeAssignment::Flat
                                : fold < 0 ? EdgeAssignment::Mountain
                                           : EdgeAssignment::Valley;
    for (int r = 0; r < rows; ++r) {
      if (f >= 0) out.fold_edges[f].push_back(static_cast<int>(p.edges.size()));
      p.edges.push_back(edge(vertex(j, r), vertex(j, r + 1), kind, fold));
    }
  }
  derive_edge_faces(p, "<sheet>");
  return out;
}

}  // namespace finseg
