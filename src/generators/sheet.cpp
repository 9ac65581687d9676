// Sheet generator. Joint placement: each panel is cut into cells; a bending joint sits at
// every cell centre and stands for exactly that cell (stiffness EI/h), so the bodies run
// from one cell centre to the next, with half cells next to creases and free or clamped
// ends. This is the midpoint rule for the curvature integral: second-order convergence.
#include "generators/sheet.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/grading.hpp"
#include "core/so3.hpp"
#include "core/text.hpp"
#include "generators/sheet_pattern_model.hpp"

namespace finseg {
namespace {

void validate_spec(const SheetSpec& s) {
  require_positive(s.length, "<api>", "sheet.length", "m");
  require_positive(s.width, "<api>", "sheet.width", "m");
  require_positive(s.thickness, "<api>", "sheet.thickness", "m");
  require_positive(s.youngs_modulus, "<api>", "material.youngs_modulus", "Pa");
  require_positive(s.density, "<api>", "material.density", "kg/m^3");
  require_positive(s.crease_refinement, "<api>", "discretisation.crease_refinement", "(ratio)");
  if (!(s.poisson_ratio >= 0 && s.poisson_ratio < 0.5)) {
    throw InputError("<api>", "material.poisson_ratio",
                     fmt::format("{}; allowed range [0, 0.5)", s.poisson_ratio));
  }
  if (s.cells_along < 1 || s.cells_across < 1) {
    throw InputError("<api>", "discretisation", "segments along and across must be >= 1");
  }
  if (!s.cell_weights.empty()) {
    if (!s.folds.empty()) {
      throw InputError("<api>", "discretisation.cell_weights", "only for sheets without folds");
    }
    if (static_cast<int>(s.cell_weights.size()) != s.cells_along) {
      throw InputError("<api>", "discretisation.cell_weights",
                       "needs one weight per segment along the length");
    }
    for (double w : s.cell_weights) require_positive(w, "<api>", "discretisation.cell_weights", "");
  }
  double prev = 0;
  for (size_t i = 0; i < s.folds.size(); ++i) {
    const FoldSpec& f = s.folds[i];
    const std::string field = fmt::format("folds[{}]", i);
    if (!(f.s > prev && f.s < s.length)) {
      throw InputError(
          "<api>", field + ".s",
          fmt::format("{} m; folds must be sorted and inside (0, {}) m", f.s, s.length));
    }
    if (!(std::abs(f.angle) <= kPi)) {
      throw InputError("<api>", field + ".angle", "fold angle must lie in [-180, 180] deg");
    }
    if (!f.law) throw InputError("<api>", field + ".law", "every fold needs a crease law");
    prev = f.s;
  }
  const int panels = static_cast<int>(s.folds.size()) + 1;
  for (int p : s.fixed_panels) {
    if (p < 0 || p >= panels) {
      throw InputError("<api>", "fixtures.fixed_panels",
                       fmt::format("panel {} does not exist (1..{})", p + 1, panels));
    }
  }
  if (!(s.damping_time >= 0)) throw InputError("<api>", "damping_time", "must be >= 0 s");
}

struct Joint {
  double s;       // position along the sheet, m
  double h;       // length of sheet the joint stands for, m
  int fold = -1;  // index into spec.folds for crease joints
};

// A beam joint of the one-row strip standing for a length h (m) of it.
Vec6 joint_stiffness(const SheetSpec& s, double h) {
  const double E = s.youngs_modulus, t = s.thickness, w = s.width;
  const double G = E / (2 * (1 + s.poisson_ratio));
  Vec6 k;
  k << E * w * t / h, kShearCorrection * G * w * t / h, kShearCorrection * G * w * t / h,
      G * w * t * t * t / 3 / h, E * w * t * t * t / 12 / h, E * t * w * w * w / 12 / h;
  const StiffnessOverride& o = s.overrides;
  if (o.axial_rigidity) k[0] = *o.axial_rigidity / h;
  if (o.shear_rigidity) k[1] = k[2] = *o.shear_rigidity / h;
  if (o.twist_rigidity) k[3] = *o.twist_rigidity / h;
  if (o.bending_rigidity) k[4] = *o.bending_rigidity / h;
  if (o.inplane_rigidity) k[5] = *o.inplane_rigidity / h;
  return k;
}

}  // namespace

std::vector<double> panel_cell_bounds(const SheetSpec& s, double a, double b, bool crease_a,
                                      bool crease_b) {
  const std::vector<double> w =
      s.cell_weights.empty()
          ? graded_cell_weights(s.cells_along, s.crease_refinement, crease_a, crease_b)
          : s.cell_weights;
  double total = 0;
  for (double x : w) total += x;
  std::vector<double> bounds{a};
  for (double x : w) bounds.push_back(bounds.back() + (b - a) * x / total);
  bounds.back() = b;
  return bounds;
}

std::vector<double> panel_starts(const SheetSpec& spec) {
  std::vector<double> starts{0.0};
  for (const FoldSpec& f : spec.folds) starts.push_back(f.s);
  starts.push_back(spec.length);
  return starts;
}

std::vector<PanelFrame> panel_frames(const SheetSpec& spec) {
  const std::vector<double> starts = panel_starts(spec);
  std::vector<PanelFrame> frames{{spec.origin_W, spec.R_W0}};
  for (std::size_t k = 0; k < spec.folds.size(); ++k) {
    const PanelFrame& p = frames.back();
    frames.push_back({p.o_W + p.R_W * Vec3(starts[k + 1] - starts[k], 0, 0),
                      p.R_W * so3_exp<double>(Vec3(0, spec.folds[k].angle, 0))});
  }
  return frames;
}

Model build_sheet_model(const SheetSpec& spec) {
  validate_spec(spec);
  // Rows across make it a plate: the pattern path's joints and cell corrections converge to
  // Kirchhoff's plate, the rows of beam joints below did not (27 % too soft in twist at 2 rows).
  if (spec.cells_across > 1) return build_sheet_pattern_model(spec);
  Model m;
  m.sheet = {spec.length,         spec.width,         spec.thickness, Vec2::Zero(),
             spec.youngs_modulus, spec.poisson_ratio, spec.density};

  // Panels, their cells and the joints along the sheet.
  const int panels = static_cast<int>(spec.folds.size()) + 1;
  const std::vector<double> panel_start = panel_starts(spec);
  std::vector<Joint> joints;
  for (int p = 0; p < panels; ++p) {
    const auto b =
        panel_cell_bounds(spec, panel_start[p], panel_start[p + 1], p > 0, p < panels - 1);
    for (size_t j = 0; j + 1 < b.size(); ++j)
      joints.push_back({0.5 * (b[j] + b[j + 1]), b[j + 1] - b[j]});
    if (p < panels - 1) {
      const double h =
          0.5 * std::min(b[b.size() - 1] - b[b.size() - 2],
                         panel_cell_bounds(spec, panel_start[p + 1], panel_start[p + 2], true,
                                           p + 1 < panels - 1)[1] -
                             panel_start[p + 1]);
      joints.push_back({panel_start[p + 1], h, p});
    }
  }
  // Body boundaries along s: sheet ends and every joint.
  std::vector<double> bs{0.0};
  for (const Joint& j : joints) bs.push_back(j.s);
  bs.push_back(spec.length);
  const int n_along = static_cast<int>(bs.size()) - 1;
  const double w = spec.width;

  const std::vector<PanelFrame> frame = panel_frames(spec);
  auto panel_of = [&](double s_mid) {
    int p = 0;
    while (p + 1 < panels && s_mid > panel_start[p + 1]) ++p;
    return p;
  };

  // Material centre of body i: body frames are the material axes, origin at the centre.
  auto centre = [&](int i) { return Vec2(0.5 * (bs[i] + bs[i + 1]), 0.5 * w); };
  for (int i = 0; i < n_along; ++i) {
    BodyDef b;
    const Vec2 c_M = centre(i);
    b.centroid_M = c_M;
    b.panel = panel_of(c_M.x());
    const double len = bs[i + 1] - bs[i];
    set_prism(b, rectangle_outline(len, w), spec.thickness,
              spec.density * (len * w * spec.thickness));
    const PanelFrame& f = frame[b.panel];
    b.R0_WB = f.R_W;
    b.p0_W = f.o_W + f.R_W * Vec3(c_M.x() - panel_start[b.panel], c_M.y(), 0);
    b.fixed = (spec.clamp_start && i == 0) ||
              std::find(spec.fixed_panels.begin(), spec.fixed_panels.end(), b.panel) !=
                  spec.fixed_panels.end();
    b.name = fmt::format("seg_r0_s{}", i);
    m.bodies.push_back(b);
  }

  for (const FoldSpec& f : spec.folds) {
    CreaseDef c;
    c.law = f.law;
    c.initial_fold_angle = f.angle;
    m.creases.push_back(c);
  }
  // Joint i joins body i (outer, e-) to body i+1 (inner, e+) on the strip's centre line.
  for (int i = 0; i + 1 < n_along; ++i) {
    const Joint& j = joints[i];
    ElementDef e;
    e.outer = i;
    e.inner = i + 1;
    const Vec2 P(j.s, 0.5 * w);
    e.c_outer_B = Vec3(P.x() - centre(i).x(), 0, 0);
    e.c_inner_B = Vec3(P.x() - centre(i + 1).x(), 0, 0);
    e.K = joint_stiffness(spec, j.h);
    e.crease = j.fold;
    e.C = spec.damping_time * e.K;
    e.name = fmt::format("{}_r0_s{}", j.fold >= 0 ? "crease" : "joint", i);
    m.elements.push_back(e);
  }
  m.finalize_dofs();
  return m;
}

MaterialPoint locate_material_point(const Model& model, double s, double y) {
  const double tol = 1e-12 * std::max(1.0, model.sheet.length);
  const Vec2 p_M(s, y);
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const BodyDef& b = model.bodies[i];
    if (b.centroid_M && polygon_contains(material_outline(b), p_M, tol)) {
      const Vec2 r = p_M - *b.centroid_M;
      return {static_cast<int>(i), Vec3(r.x(), r.y(), 0)};
    }
  }
  const Vec2& o = model.sheet.origin_M;
  throw InputError(
      model.source, "at",
      fmt::format("material point ({}, {}) m lies outside the sheet [{}, {}] x [{}, {}]", s, y,
                  o.x(), o.x() + model.sheet.length, o.y(), o.y() + model.sheet.width));
}

Model clamped_paper_sheet(int n) {
  SheetSpec spec;
  spec.length = spec.width = 0.2;
  spec.thickness = 1e-4;
  spec.youngs_modulus = 3e9;
  spec.poisson_ratio = 0.3;
  spec.density = 800;
  spec.cells_along = spec.cells_across = n;
  spec.clamp_start = true;
  Model m = build_sheet_model(spec);
  m.gravity_W = Vec3(0, 0, -9.81);
  return m;
}

}  // namespace finseg
