// The `solver:` and `outputs:` sections of a scene file (docs/scene.md).
#include <algorithm>

#include "scene/scene_parts.hpp"

namespace finseg {

std::string solver_name(SolverKind kind) {
  switch (kind) {
    case SolverKind::Explicit:
      return "explicit";
    case SolverKind::Implicit:
      return "implicit";
    case SolverKind::Static:
      break;
  }
  return "static";
}

std::string scheme_name(ImplicitScheme scheme) {
  return scheme == ImplicitScheme::GeneralizedAlpha ? "generalized_alpha" : "backward_euler";
}

std::string error_measure_name(bool at_points) {
  return at_points ? "points" : "dofs";
}

SolverSettings read_solver_section(const Fields& root) {
  const Fields f(
      root.node("solver"), root.context("solver"),
      {"type", "t_end", "output_interval", "dt", "dt_min", "dt_max", "rtol", "atol", "load_steps",
       "max_iterations", "tolerance", "scheme", "rho_inf", "jacobian_reuse", "jacobian_max_age",
       "krylov_steps", "newton_tolerance", "error_measure"});
  SolverSettings s;
  const std::string type = f.word("type", "static");
  if (type == "static") {
    s.kind = SolverKind::Static;
  } else if (type == "implicit") {
    s.kind = SolverKind::Implicit;
  } else if (type == "explicit") {
    s.kind = SolverKind::Explicit;
  } else {
    f.fail("type", "'" + type + "'; allowed: static, implicit, explicit");
  }
  s.t_end = f.number("t_end", s.t_end, positive("s"));
  s.output_interval =
      f.number("output_interval", s.output_interval, non_negative("s (0: t_end/100)"));
  s.dt = f.number("dt", s.dt, non_negative("s (0: automatic)"));
  s.dt_min = f.number("dt_min", s.dt_min, positive("s"));
  s.dt_max = f.number("dt_max", s.dt_max, non_negative("s (0: output_interval)"));
  s.rtol = f.number("rtol", s.rtol, positive(""));
  s.atol = f.number("atol", s.atol, positive("m and rad"));
  const std::string scheme = f.word("scheme", scheme_name(s.scheme));
  if (scheme == "generalized_alpha") {
    s.scheme = ImplicitScheme::GeneralizedAlpha;
  } else if (scheme == "backward_euler") {
    s.scheme = ImplicitScheme::BackwardEuler;
  } else {
    f.fail("scheme", "'" + scheme + "'; allowed: generalized_alpha, backward_euler");
  }
  s.rho_inf = f.number("rho_inf", s.rho_inf, interval(0, 1, false, false));
  s.load_steps = f.integer("load_steps", s.load_steps, 1, 1000000);
  // Absent, it stays 0: the solver's own (newton_iterations()).
  s.max_iterations = f.integer("max_iterations", s.max_iterations, 1, 100000);
  s.tolerance = f.number("tolerance", s.tolerance, positive("(relative)"));
  s.jacobian_reuse = f.flag("jacobian_reuse", s.jacobian_reuse);
  s.krylov_steps = f.flag("krylov_steps", s.krylov_steps);
  s.jacobian_max_age = f.integer("jacobian_max_age", s.jacobian_max_age, 1, 1000);
  s.newton_tolerance =
      f.number("newton_tolerance", s.newton_tolerance, interval(0, 1, true, false));  // (0, 1]
  const std::string measure = f.word("error_measure", error_measure_name(s.error_at_points));
  if (measure != "points" && measure != "dofs") {
    f.fail("error_measure", "'" + measure + "'; allowed: dofs (m and rad), points (m)");
  }
  s.error_at_points = measure == "points";
  if (s.dt > s.t_end) f.fail("dt", "must not exceed t_end");
  return s;
}

void read_folding_section(const Fields& root, Scene& scene) {
  if (!root.has("folding")) return;
  const Fields f(root.node("folding"), root.context("folding"),
                 {"fraction", "duration", "solver", "coarse_subdivisions"});
  FoldingSpec s;
  s.fraction = f.number("fraction", s.fraction, interval(0, 1, true, false));
  s.duration = f.number("duration", s.duration, positive("s"));
  s.coarse_subdivisions = f.integer("coarse_subdivisions", 0, 0, 63);
  if (s.coarse_subdivisions > 0) {
    // A coarser cut of the same pattern: only a pattern cut by subdivisions has one.
    const YAML::Node pattern = root.node("pattern");
    if (!pattern || pattern["segment_size"]) {
      f.fail("coarse_subdivisions", "needs a pattern: section cut by subdivisions");
    }
    const int fine = pattern["subdivisions"] ? pattern["subdivisions"].as<int>() : 2;
    if (fine < 2) f.fail("coarse_subdivisions", "needs pattern.subdivisions of 2 or more");
    s.coarse_subdivisions = f.integer("coarse_subdivisions", 0, 0, fine - 1);
  }
  scene.folding = s;
  scene.folding_solver = read_solver_section(f);
  // The fine run starts where the coarse fold ends, at the end of the rest angles' ramp: a
  // load scale the static solver can start at, not a time a dynamic one would ramp from.
  if (s.coarse_subdivisions > 0 && scene.folding_solver.kind != SolverKind::Static) {
    f.fail("coarse_subdivisions", "needs the static folding solver (folding.solver.type: static)");
  }
  bool any_target = false;
  for (const CreaseDef& c : scene.model.creases)
    any_target = any_target || c.target_fold_angle != 0;
  if (!any_target) {
    root.fail("folding",
              "no crease has a target fold angle: folding needs a pattern with "
              "edges_foldAngle or folded coordinates");
  }
}

OutputSettings read_outputs_section(const Fields& root, const Model& m) {
  const Fields f(root.node("outputs"), root.context("outputs"), {"vtk", "html", "plot", "phases"});
  const bool pulled = !m.drives.empty();
  OutputSettings o;
  o.vtk = f.flag("vtk", pulled);
  o.html = f.flag("html", pulled);
  o.plot = f.flag("plot", pulled);
  const int panels = panel_count(m);
  PhaseSettings& p = o.phases;
  const auto watched_exist = [&] {
    return std::all_of(p.panels.begin(), p.panels.end(), [&](int q) { return q <= panels; });
  };
  p.enabled = pulled && watched_exist();
  const YAML::Node node = f.node("phases");
  if (node && node.IsScalar()) {
    p.enabled = f.flag("phases", p.enabled);
  } else if (node) {
    const Fields ph(node, f.context("phases"), {"enabled", "panels", "bend_threshold_deg"});
    p.enabled = ph.flag("enabled", true);
    if (ph.has("panels")) p.panels = ph.integers("panels", 1, panels);
    if (p.panels.empty()) ph.fail("panels", "must list at least one panel (1-based)");
    p.bend_threshold =
        ph.number("bend_threshold_deg", p.bend_threshold / kDegToRad, positive("deg")) * kDegToRad;
  }
  if (p.enabled && m.drives.empty()) {
    f.fail("phases", "deployment phases need a drive (the pull displacement)");
  }
  if (p.enabled && !watched_exist()) {
    f.fail("phases", "watched panels must exist (1.." + std::to_string(panels) + ")");
  }
  return o;
}

}  // namespace finseg
