#include "patterns/zigzag_pattern.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "elements/crease_law.hpp"

namespace finseg {
namespace {

PatternEdge edge(int a, int b, EdgeAssignment kind, double angle = 0) {
  PatternEdge e;
  e.vertices = {a, b};
  e.assignment = kind;
  e.fold_angle = angle;
  return e;
}

// A line across the flat strip at x (m): a crease (index into the sheet's folds), a cell
// boundary inside a panel (F) or one of the strip's two ends.
struct CutLine {
  double x = 0;
  int panel = 0;  // the panel the line starts (the last panel for the far end)
  int fold = -1;
};

std::vector<CutLine> cut_lines(const ZigzagSpec& spec, const SheetSpec& sheet, bool cells) {
  const int n = spec.panels;
  const double lp = spec.length / n;
  std::vector<CutLine> lines;
  for (int k = 0; k < n; ++k) {
    const double a = k * lp, b = (k + 1) * lp;
    lines.push_back({a, k, k > 0 ? k - 1 : -1});
    if (!cells) continue;
    const std::vector<double> bounds = panel_cell_bounds(sheet, a, b, k > 0, k + 1 < n);
    for (std::size_t j = 1; j + 1 < bounds.size(); ++j) lines.push_back({bounds[j], k});
  }
  lines.push_back({spec.length, n - 1, -1});
  return lines;
}

// Panel (0-based) that face f of the strip's pattern lies in: by its middle along x.
int panel_of_face(const CreasePattern& p, int f, const ZigzagSpec& spec) {
  double x = 0;
  for (int v : p.faces[f]) x += p.vertices_flat_m[v].x();
  x /= static_cast<double>(p.faces[f].size());
  const int k = static_cast<int>(std::floor(x / (spec.length / spec.panels)));
  return std::clamp(k, 0, spec.panels - 1);
}

}  // namespace

CreasePattern zigzag_crease_pattern(const ZigzagSpec& spec, bool cells) {
  const SheetSpec sheet = zigzag_sheet(spec);  // validates the spec
  const int n = spec.panels;
  const double lp = spec.length / n, w = spec.width;
  CreasePattern p;
  p.meta.file_creator = "finseg";
  p.meta.frame_title = fmt::format("zigzag strip, {} panels", n);
  p.has_fold_angles = true;
  // Crease line k's folded position and the orientation of panel k.
  std::vector<Vec3> crease_W{sheet.origin_W};
  std::vector<Mat3> R_W{sheet.R_W0};
  for (int k = 0; k + 1 < n; ++k) {
    crease_W.push_back(crease_W[k] + R_W[k] * Vec3(lp, 0, 0));
    R_W.push_back(R_W[k] * so3_exp<double>(Vec3(0, sheet.folds[k].angle, 0)));
  }
  const std::vector<CutLine> lines = cut_lines(spec, sheet, cells);
  const int m = static_cast<int>(lines.size());
  for (int j = 0; j < m; ++j) {
    // Vertices 2j (y = 0) and 2j + 1 (y = width) on line j.
    const CutLine& l = lines[j];
    const Vec3 base_W = crease_W[l.panel] + R_W[l.panel] * Vec3(l.x - l.panel * lp, 0, 0);
    p.vertices_flat_m.emplace_back(l.x, 0);
    p.vertices_flat_m.emplace_back(l.x, w);
    p.vertices_folded_m.push_back(base_W);
    p.vertices_folded_m.push_back(base_W + R_W[l.panel] * Vec3(0, w, 0));
    if (j + 1 < m) p.faces.push_back({2 * j, 2 * j + 2, 2 * j + 3, 2 * j + 1});
  }
  for (int j = 0; j + 1 < m; ++j) {
    p.edges.push_back(edge(2 * j, 2 * j + 2, EdgeAssignment::Boundary));
    p.edges.push_back(edge(2 * j + 3, 2 * j + 1, EdgeAssignment::Boundary));
  }
  p.edges.push_back(edge(1, 0, EdgeAssignment::Boundary));
  p.edges.push_back(edge(2 * m - 2, 2 * m - 1, EdgeAssignment::Boundary));
  for (int j = 1; j + 1 < m; ++j) {
    const int f = lines[j].fold;
    if (f < 0) {
      p.edges.push_back(edge(2 * j, 2 * j + 1, EdgeAssignment::Flat));
      continue;
    }
    // The sheet's fold angle turns the next panel about +y (down for a peak); FOLD's is
    // positive for a valley seen from +z of the flat pattern: the opposite sign.
    const double fold = -sheet.folds[f].angle;
    p.edges.push_back(
        edge(2 * j, 2 * j + 1, fold < 0 ? EdgeAssignment::Mountain : EdgeAssignment::Valley, fold));
  }
  derive_edge_faces(p, "<zigzag>");
  return p;
}

PatternSheetSpec zigzag_pattern_sheet(const ZigzagSpec& spec) {
  const SheetSpec sheet = zigzag_sheet(spec);
  if (spec.segments_across != 1) {
    throw InputError("<api>", "segments_across",
                     fmt::format("{}; the pattern path cuts the strip into cells along it only",
                                 spec.segments_across));
  }
  const StiffnessOverride& o = spec.overrides;
  if (o.twist_rigidity || o.inplane_rigidity || o.axial_rigidity || o.shear_rigidity) {
    throw InputError("<api>", "overrides",
                     "the pattern path takes the bending rigidity alone (a plate rigidity)");
  }
  PatternSheetSpec s;
  if (o.bending_rigidity) {
    // The one-row strip's cells condense k_yy out (free edges): a uniform bending stores
    // D (1 - nu^2) w per length, the beam's EI.
    const double nu = sheet.poisson_ratio;
    s.bending_rigidity = *o.bending_rigidity / (spec.width * (1 - nu * nu));
  }
  s.thickness = sheet.thickness;
  s.youngs_modulus = sheet.youngs_modulus;
  s.poisson_ratio = sheet.poisson_ratio;
  s.density = sheet.density;
  s.damping_time = sheet.damping_time;
  s.subdivisions = 1;
  s.crease_law_length = spec.width;
  s.laws_rest_at_pattern = false;  // the strip's laws rest where the generator puts them
  s.crease_bending_in_series = true;
  for (std::size_t k = 0; k < sheet.folds.size(); ++k) {
    const FoldSpec& f = sheet.folds[k];
    auto& law = f.angle > 0 ? s.mountain_law : s.valley_law;
    if (!law) {
      law = f.law;
    } else if (law->describe() != f.law->describe()) {
      throw InputError("<api>", fmt::format("crease_laws[{}]", k),
                       "the pattern path gives all peaks one law and all valleys one law");
    }
  }
  const CreasePattern p = zigzag_crease_pattern(spec, true);
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    if (std::find(sheet.fixed_panels.begin(), sheet.fixed_panels.end(),
                  panel_of_face(p, static_cast<int>(f), spec)) != sheet.fixed_panels.end()) {
      s.fixed_faces.push_back(static_cast<int>(f));
    }
  }
  return s;
}

Model build_zigzag_pattern_model(const ZigzagSpec& spec, bool crease_bending_in_series) {
  const CreasePattern p = zigzag_crease_pattern(spec, true);
  PatternSheetSpec sheet = zigzag_pattern_sheet(spec);
  sheet.crease_bending_in_series = crease_bending_in_series;
  Model m = build_pattern_model(p, sheet);
  // Faces are the cells; the contact groups and the panels' bending watch whole panels.
  for (BodyDef& b : m.bodies) b.panel = panel_of_face(p, b.panel, spec);
  add_zigzag_rig(m, spec);
  return m;
}

}  // namespace finseg
