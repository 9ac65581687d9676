// Cantilever strip of the paper's bending test (section 3.1).
#include "generators/cantilever.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"
#include "core/text.hpp"

namespace finseg {

void validate(const CantileverSpec& s, const std::string& src) {
  require_positive(s.length, src, "length", "m");
  require_positive(s.width, src, "width", "m");
  require_positive(s.thickness, src, "thickness", "m");
  require_positive(s.youngs_modulus, src, "modulus", "Pa");
  require_positive(s.density, src, "density", "kg/m^3");
  if (!(s.poisson_ratio >= 0 && s.poisson_ratio < 0.5)) {
    throw InputError(src, "poisson", fmt::format("{}; allowed range [0, 0.5)", s.poisson_ratio));
  }
  if (s.segments < 1) {
    throw InputError(src, "segments", fmt::format("{}; must be >= 1", s.segments));
  }
  if (s.segments_across < 1) {
    throw InputError(src, "segments_across", fmt::format("{}; must be >= 1", s.segments_across));
  }
  if (!s.tip_force.allFinite()) throw InputError(src, "tip_force", "must be finite (N)");
  if (!s.tip_moment.allFinite()) throw InputError(src, "tip_moment", "must be finite (N m)");
  if (!(s.damping_time >= 0)) {
    throw InputError(src, "damping_time", fmt::format("{} s; must be >= 0", s.damping_time));
  }
}

SheetSpec cantilever_sheet(const CantileverSpec& c) {
  SheetSpec s;
  s.length = c.length;
  s.width = c.width;
  s.thickness = c.thickness;
  s.youngs_modulus = c.youngs_modulus;
  s.poisson_ratio = c.poisson_ratio;
  s.density = c.density;
  s.cells_along = c.segments;
  s.cells_across = c.segments_across;
  s.clamp_start = true;
  s.damping_time = c.damping_time;
  return s;
}

Model build_cantilever_model(const CantileverSpec& c) {
  validate(c);
  Model m = build_sheet_model(cantilever_sheet(c));
  const double row = c.width / c.segments_across;
  const bool loaded = c.tip_force.squaredNorm() > 0 || c.tip_moment.squaredNorm() > 0;
  for (int r = 0; loaded && r < c.segments_across; ++r) {
    const MaterialPoint p = locate_material_point(m, c.length, (r + 0.5) * row);
    m.loads.push_back(
        {p.body, p.r_B, c.tip_force / c.segments_across, c.tip_moment / c.segments_across, false});
  }
  if (c.gravity) m.gravity_W = Vec3(0, 0, -9.81);
  const MaterialPoint tip = locate_material_point(m, c.length, 0.5 * c.width);
  ProbeDef probe;
  probe.name = "tip";
  probe.kind = ProbeKind::Point;
  probe.body = tip.body;
  probe.point_B = tip.r_B;
  m.probes.push_back(probe);
  validate(m);
  return m;
}

double bending_rigidity(const CantileverSpec& c) {
  return c.youngs_modulus * c.width * std::pow(c.thickness, 3) / 12.0;
}

}  // namespace finseg
