#include "scene/scene_writer.hpp"

#include <fmt/format.h>

namespace finseg {

std::string yaml_number(double x) {
  return fmt::format("{}", x);  // shortest text that reads back to the same double
}

std::string yaml_vector(const Vec3& v) {
  return fmt::format("[{}, {}, {}]", yaml_number(v.x()), yaml_number(v.y()), yaml_number(v.z()));
}

namespace {

std::string num(double x) {
  return yaml_number(x);
}
std::string vec(const Vec3& v) {
  return yaml_vector(v);
}

std::string header(const std::string& what, const std::string& command) {
  return fmt::format(
      "# finseg scene: {}\n"
      "# written by `{}`; docs/scene.md describes every key.\n"
      "# Units: SI (m, Pa, kg/m^3, N, N m, s, m/s^2); angles in degrees (keys ending in _deg).\n",
      what, command);
}

std::string material(double E, double nu, double rho, double damping_time) {
  return fmt::format(
      "material:\n"
      "  youngs_modulus: {}   # Pa\n"
      "  poisson_ratio: {}\n"
      "  density: {}   # kg/m^3\n"
      "  damping_time: {}   # s, element damping C = damping_time * K\n",
      num(E), num(nu), num(rho), num(damping_time));
}

std::string sheet(double L, double w, double t, const char* length_note) {
  return fmt::format(
      "sheet:\n"
      "  length: {}   # m, {}\n"
      "  width: {}   # m, along y\n"
      "  thickness: {}   # m\n",
      num(L), length_note, num(w), num(t));
}

std::string solver_section(const SolverSettings& s) {
  return fmt::format(
      "solver:\n"
      "  type: {}\n"
      "  t_end: {}   # s (dynamic solvers)\n"
      "  output_interval: {}   # s (0: t_end / 100)\n"
      "  dt: {}   # s (explicit: fixed step, 0 automatic; implicit: first step)\n"
      "  load_steps: {}   # static: initial load increments\n"
      "  max_iterations: {}\n"
      "  tolerance: {}   # static: residual relative to the load scale\n",
      solver_name(s.kind), num(s.t_end), num(s.output_interval), num(s.dt), s.load_steps,
      newton_iterations(s), num(s.tolerance));
}

}  // namespace

std::string yaml_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += (c == '\'') ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string cantilever_scene(const CantileverSpec& c, const SolverSettings& solver) {
  validate(c);
  std::string y = header("cantilever bending test (paper section 3.1)", "finseg gen cantilever");
  y += "title: cantilever\n";
  y += material(c.youngs_modulus, c.poisson_ratio, c.density, c.damping_time);
  y += sheet(c.length, c.width, c.thickness, "free length from the clamp (x = 0) to the tip");
  y += fmt::format(
      "discretisation:\n"
      "  segments: {}   # along the length\n"
      "  segments_across: {}\n"
      "fixtures:\n"
      "  clamp_start: true   # the strip is clamped at x = 0\n"
      "gravity: {}   # m/s^2\n",
      c.segments, c.segments_across, vec(c.gravity ? Vec3(0, 0, -9.81) : Vec3::Zero()));
  const bool loaded = c.tip_force.squaredNorm() > 0 || c.tip_moment.squaredNorm() > 0;
  const double row = c.width / c.segments_across;
  if (loaded) {
    y += "loads:   # dead tip load, shared by the free-edge segment of each row (N, N m)\n";
    for (int r = 0; r < c.segments_across; ++r) {
      y += fmt::format("  - {{at: {{s: {}, y: {}}}, force: {}, moment: {}}}\n", num(c.length),
                       num((r + 0.5) * row), vec(c.tip_force / c.segments_across),
                       vec(c.tip_moment / c.segments_across));
    }
  }
  y += fmt::format(
      "probes:\n"
      "  - {{name: tip, type: point, at: {{s: {}, y: {}}}}}   # mid-point of the free edge\n",
      num(c.length), num(0.5 * c.width));
  y += solver_section(solver);
  y += "outputs: {vtk: false, html: false, plot: false}\n";
  return y;
}

std::string zigzag_scene(const ZigzagSceneOptions& o, const SolverSettings& solver) {
  ZigzagSpec s = o.spec;
  s.fold_angle = o.fold_angle_deg * kDegToRad;
  validate(s);
  std::string y = header("zigzag strip pulled open (paper section 4)", "finseg gen zigzag");
  y += "title: zigzag\n";
  y += material(s.youngs_modulus, s.poisson_ratio, s.density, s.damping_time);
  y += sheet(s.length, s.width, s.thickness, "whole strip, along the panels");
  y += fmt::format(
      "discretisation:\n"
      "  segments: {}   # per panel\n"
      "  segments_across: {}\n"
      "  crease_refinement: {}   # middle cell / cell next to a crease\n",
      s.segments_per_panel, s.segments_across, num(s.crease_refinement));
  if (s.overrides.bending_rigidity) {
    y += fmt::format("stiffness:\n  bending_rigidity: {}   # N m^2, whole width\n",
                     num(*s.overrides.bending_rigidity));
  }
  std::string panels;
  for (int p : s.fixed_panels) panels += (panels.empty() ? "" : ", ") + std::to_string(p);
  y += fmt::format("fixtures:\n  panels: [{}]   # clamped panels, 1-based\n", panels);
  y += fmt::format("gravity: {}   # m/s^2\n", vec(s.gravity ? Vec3(0, 0, -9.81) : Vec3::Zero()));
  if (!s.contact) y += "contact: {enabled: false}\n";
  y += fmt::format(
      "zigzag:\n"
      "  panels: {}\n"
      "  fold_angle_deg: {}   # between a panel and the horizontal\n",
      s.panels, num(o.fold_angle_deg));
  if (!s.pattern.empty()) y += fmt::format("  pattern: {}   # P peak, V valley\n", s.pattern);
  if (!o.crease_law_file.empty()) {
    const std::string pressing =
        o.pressing_time ? fmt::format(", pressing_time: {}", num(*o.pressing_time)) : "";
    y += fmt::format("  crease_law: {{type: measured, file: {}{}}}   # pressing_time in s\n",
                     yaml_quote(o.crease_law_file), pressing);
  } else if (o.crease_stiffness) {
    y += "  crease_laws:   # linear, resting at the initial fold (N m/rad, signed deg)\n";
    for (int k = 0; k + 1 < s.panels; ++k) {
      y += fmt::format("    - {{type: linear, stiffness: {}, rest_angle_deg: {}}}\n",
                       num(*o.crease_stiffness), num(zigzag_fold_angle(s, k) / kDegToRad));
    }
  }
  y += fmt::format(
      "  pulled_crease: {}   # 1-based, between panels {} and {}\n"
      "  pull_direction: {}\n"
      "  pull_step: {}   # m per equilibrium (static solver)\n"
      "  pull_travel: {}   # m (0: 90 % of the travel that straightens the panels)\n"
      "  gauge_stiffness: {}   # N/m\n",
      s.pulled_crease, s.pulled_crease, s.pulled_crease + 1, vec(s.pull_direction_W),
      num(s.pull_step), num(s.pull_travel), num(s.gauge_stiffness));
  if (o.pull_speed) {
    y += fmt::format("  pull_speed: {}   # m/s (dynamic solvers)\n", num(*o.pull_speed));
  }
  y += solver_section(solver);
  return y;
}

}  // namespace finseg
