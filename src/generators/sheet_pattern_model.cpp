#include "generators/sheet_pattern_model.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.hpp"

namespace finseg {
namespace {

// The pattern-path material, laws, clamps and fixed panels of `spec` for its pattern `sp`.
PatternSheetSpec sheet_pattern_spec(const SheetSpec& spec, const SheetPattern& sp) {
  const StiffnessOverride& o = spec.overrides;
  const char* refused = o.twist_rigidity     ? "twist_rigidity"
                        : o.inplane_rigidity ? "inplane_rigidity"
                        : o.axial_rigidity   ? "axial_rigidity"
                        : o.shear_rigidity   ? "shear_rigidity"
                                             : nullptr;
  if (refused != nullptr) {
    throw InputError("<api>", fmt::format("stiffness.{}", refused),
                     "a sheet cut into rows (segments_across > 1) is a plate and takes "
                     "bending_rigidity alone; the others need segments_across: 1");
  }
  PatternSheetSpec s;
  if (o.bending_rigidity) {
    // Free long sides: a uniform bending stores D (1 - nu^2) w per length, the beam's EI.
    const double nu = spec.poisson_ratio;
    s.bending_rigidity = *o.bending_rigidity / (spec.width * (1 - nu * nu));
  }
  s.thickness = spec.thickness;
  s.youngs_modulus = spec.youngs_modulus;
  s.poisson_ratio = spec.poisson_ratio;
  s.density = spec.density;
  s.damping_time = spec.damping_time;
  s.subdivisions = 1;
  s.crease_law_length = spec.width;
  s.laws_rest_at_pattern = false;  // the laws rest where the generator puts them
  for (std::size_t k = 0; k < spec.folds.size(); ++k) {
    s.edge_laws.push_back({sp.fold_edges[k], spec.folds[k].law});
  }
  for (std::size_t f = 0; f < sp.face_panel.size(); ++f) {
    const bool fixed =
        sp.face_clamp[f] || std::find(spec.fixed_panels.begin(), spec.fixed_panels.end(),
                                      sp.face_panel[f]) != spec.fixed_panels.end();
    if (fixed) s.fixed_faces.push_back(static_cast<int>(f));
  }
  return s;
}

}  // namespace

Model build_sheet_pattern_model(const SheetSpec& spec, bool crease_bending_in_series) {
  const SheetPattern sp = sheet_crease_pattern(spec, true);
  PatternSheetSpec s = sheet_pattern_spec(spec, sp);
  s.crease_bending_in_series = crease_bending_in_series;
  Model m = build_pattern_model(sp.pattern, s);
  for (BodyDef& b : m.bodies) b.panel = sp.face_panel[b.panel];
  m.sheet.length = spec.length;
  m.sheet.origin_M = Vec2::Zero();
  return m;
}

}  // namespace finseg
