#include "generators/zigzag.hpp"

#include <fmt/format.h>
#include <cmath>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "core/text.hpp"
#include "elements/crease_law.hpp"

namespace finseg {
namespace {

char crease_kind(const ZigzagSpec& s, int k) {
  if (!s.pattern.empty()) return s.pattern[k];
  return k % 2 == 0 ? 'P' : 'V';
}

double panel_length(const ZigzagSpec& s) {
  return s.length / s.panels;
}

}  // namespace

ContactDef zigzag_contact_defaults() {
  ContactDef c;
  c.enabled = true;
  c.stiffness = 3.0e7;  // N/m^1.5: 1 N at 10 um, a tenth of the paper's thickness
  c.exponent = 1.5;
  c.damping_law = ContactDamping::Impact;
  c.damping = 4.4;  // N s/m: critical for a 32 mg segment on k_lin = 1.5e5 N/m
  c.damping_depth = 1e-5;
  c.friction = FrictionModel::Anchor;  // the static solver has no velocities
  c.mu_static = 0.5;
  c.mu_dynamic = 0.4;
  c.stiction_speed = 1e-4;
  c.friction_speed = 1e-3;
  c.tangential_stiffness = 1.5e5;
  c.tangential_damping = 4.4;
  return c;
}

std::vector<std::vector<int>> adjacent_panel_groups(int panels) {
  std::vector<std::vector<int>> g;
  for (int p = 0; p + 1 < panels; ++p) g.push_back({p, p + 1});
  return g;
}

void validate(const ZigzagSpec& s, const std::string& src) {
  require_positive(s.length, src, "length", "m");
  require_positive(s.width, src, "width", "m");
  require_positive(s.thickness, src, "thickness", "m");
  require_positive(s.pull_step, src, "pull_step", "m");
  require_positive(s.gauge_stiffness, src, "gauge_stiffness", "N/m");
  if (s.panels < 2) throw InputError(src, "panels", fmt::format("{}; must be >= 2", s.panels));
  if (!(s.fold_angle > 0 && s.fold_angle < kPi / 2)) {
    throw InputError(
        src, "fold_angle",
        fmt::format("{:.4g} deg; allowed range (0, 90) deg", s.fold_angle / kDegToRad));
  }
  if (!s.pattern.empty()) {
    if (static_cast<int>(s.pattern.size()) != s.panels - 1) {
      throw InputError(src, "pattern",
                       fmt::format("needs {} letters P/V, one per crease", s.panels - 1));
    }
    for (char c : s.pattern) {
      if (c != 'P' && c != 'V') throw InputError(src, "pattern", "letters must be P or V");
    }
  }
  if (static_cast<int>(s.fixed_panels.size()) >= s.panels) {
    throw InputError(src, "fixed_panels",
                     fmt::format("{} clamped panels but only {} panels: at least one must move",
                                 s.fixed_panels.size(), s.panels));
  }
  for (int p : s.fixed_panels) {
    if (p < 1 || p > s.panels) {
      throw InputError(src, "fixed_panels",
                       fmt::format("panel {} does not exist (1..{})", p, s.panels));
    }
  }
  if (s.pulled_crease < 1 || s.pulled_crease > s.panels - 1) {
    throw InputError(
        src, "pulled_crease",
        fmt::format("crease {} does not exist (1..{})", s.pulled_crease, s.panels - 1));
  }
  if (std::abs(s.pull_direction_W.norm() - 1) > 1e-9) {
    throw InputError(src, "pull_direction", "must be a unit vector");
  }
  if (s.pull_travel < 0) throw InputError(src, "pull_travel", "must be >= 0 m (0: default)");
  const size_t nl = s.crease_laws.size();
  if (nl != 0 && nl != 1 && nl != static_cast<size_t>(s.panels - 1)) {
    throw InputError(src, "crease_laws", "give one law, or one per crease");
  }
}

double zigzag_fold_angle(const ZigzagSpec& s, int k) {
  // Panels alternate between +fold_angle and -fold_angle of elevation, so a peak turns the
  // sheet down by twice the fold angle (+ about y) and a valley turns it up (-).
  return (crease_kind(s, k) == 'P' ? 2.0 : -2.0) * s.fold_angle;
}

double zigzag_deployed_travel(const ZigzagSpec& s) {
  // Nearest fixed panel on each side of the pulled crease bounds the free linkage.
  const double Lp = panel_length(s);
  double best = INFINITY;
  for (int p : s.fixed_panels) {
    // Crease index of the fixed panel's edge facing the pulled crease (1-based creases).
    const int edge = p <= s.pulled_crease ? p : p - 1;
    const int links = std::abs(s.pulled_crease - edge);
    if (links == 0) continue;
    const double horizontal = links * Lp * std::cos(s.fold_angle);
    const double reach = links * Lp;
    best = std::min(best, std::sqrt(reach * reach - horizontal * horizontal));
  }
  return std::isfinite(best) ? best : Lp;
}

double zigzag_default_travel(const ZigzagSpec& s) {
  return 0.9 * zigzag_deployed_travel(s);
}

SheetSpec zigzag_sheet(const ZigzagSpec& s) {
  validate(s);
  SheetSpec sheet;
  sheet.length = s.length;
  sheet.width = s.width;
  sheet.thickness = s.thickness;
  sheet.youngs_modulus = s.youngs_modulus;
  sheet.poisson_ratio = s.poisson_ratio;
  sheet.density = s.density;
  sheet.cells_along = s.segments_per_panel;
  sheet.cells_across = s.segments_across;
  sheet.crease_refinement = s.crease_refinement;
  sheet.damping_time = s.damping_time;
  sheet.overrides = s.overrides;
  const bool first_rises = crease_kind(s, 0) == 'P';
  sheet.R_W0 = so3_exp<double>(Vec3(0, first_rises ? -s.fold_angle : s.fold_angle, 0));
  const double Lp = panel_length(s);
  for (int k = 0; k + 1 < s.panels; ++k) {
    FoldSpec f;
    f.s = (k + 1) * Lp;
    f.angle = zigzag_fold_angle(s, k);
    if (s.crease_laws.empty()) {
      // Linear paper crease, resting in the folded state (docs/zigzag.md).
      f.law = std::make_shared<LinearCreaseLaw>(2.7e-3 * s.width / 0.04, f.angle);
    } else {
      f.law = s.crease_laws.size() == 1 ? s.crease_laws[0] : s.crease_laws[k];
    }
    sheet.folds.push_back(f);
  }
  for (int p : s.fixed_panels) sheet.fixed_panels.push_back(p - 1);
  return sheet;
}

Model build_zigzag_model(const ZigzagSpec& s) {
  Model m = build_sheet_model(zigzag_sheet(s));
  add_zigzag_rig(m, s);
  return m;
}

void add_zigzag_rig(Model& m, const ZigzagSpec& s) {
  if (s.gravity) m.gravity_W = Vec3(0, 0, -9.81);
  m.contact = s.contact_settings;
  m.contact.enabled = s.contact;
  if (m.contact.groups.empty()) m.contact.groups = adjacent_panel_groups(s.panels);
  const double s_crease = s.pulled_crease * panel_length(s);
  const MaterialPoint at = locate_material_point(m, s_crease, 0.5 * s.width);
  DriveDef d;
  d.name = "gauge";
  d.body = at.body;
  d.point_B = at.r_B;
  d.start_W = m.bodies[at.body].p0_W + m.bodies[at.body].R0_WB * at.r_B;
  d.direction_W = s.pull_direction_W;
  d.stiffness = s.gauge_stiffness;
  d.step = s.pull_step;
  d.travel = s.pull_travel > 0 ? s.pull_travel : zigzag_default_travel(s);
  d.speed = d.travel;  // dynamic solvers: the whole travel in 1 s unless changed
  d.deployed_at = zigzag_deployed_travel(s);
  m.drives.push_back(d);
  m.probes.push_back({"gauge", ProbeKind::Drive, -1, Vec3::Zero(), {0}});  // drive 0
  m.probes.push_back({"reaction", ProbeKind::Reaction, -1, Vec3::Zero(), {}});
  m.probes.push_back({"energy", ProbeKind::Energy, -1, Vec3::Zero(), {}});
  validate(m);
}

}  // namespace finseg
