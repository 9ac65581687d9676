#include "fitting/fit_spec.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "core/error.hpp"
#include "core/text.hpp"
#include "scene/yaml_fields.hpp"

namespace finseg {
namespace {

namespace fs = std::filesystem;

FitParameter read_parameter(const Fields& p) {
  FitParameter fp;
  fp.paths = p.node("path").IsSequence() ? p.words("path")
                                         : std::vector<std::string>{p.required_word("path")};
  if (fp.paths.empty()) p.fail("path", "a --set path or a list of them");
  for (const std::string& path : fp.paths) {
    try {
      parse_override(path + "=0");  // the path's own syntax
    } catch (const InputError& e) {
      p.fail("path", e.what());
    }
  }
  fp.path = fp.paths.front();
  fp.initial = p.number("initial", any_finite(""));
  fp.lower = p.number("lower", -INFINITY, any_finite(""));
  fp.upper = p.number("upper", INFINITY, any_finite(""));
  if (!(fp.lower < fp.upper)) p.fail("upper", fmt::format("must exceed lower ({:g})", fp.lower));
  if (!(fp.initial >= fp.lower && fp.initial <= fp.upper)) {
    p.fail("initial", fmt::format("must lie in [lower, upper] = [{:g}, {:g}]", fp.lower, fp.upper));
  }
  if (p.has("scale")) {
    fp.scale = p.number("scale", positive(""));
  } else if (fp.initial == 0) {
    p.fail("scale", "required (> 0, the parameter's typical size) when initial is 0");
  } else {
    fp.scale = std::abs(fp.initial);
  }
  return fp;
}

// The residuals' displacements of a curve (FitCurve::x).
std::vector<double> curve_grid(const FitCurve& c, const Fields& f) {
  double a = -INFINITY, b = INFINITY;
  for (const ForceCurve& r : c.runs) a = std::max(a, r.x.front()), b = std::min(b, r.x.back());
  a = std::max(a, c.window.lo), b = std::min(b, c.window.hi);
  if (!(b > a)) {
    f.fail(c.window.lo > -INFINITY ? "window_mm" : "measurements",
           "the measurements' displacement ranges (cut to window_mm) do not overlap");
  }
  std::vector<double> x;
  if (c.samples > 0) {
    for (int i = 0; i < c.samples; ++i) x.push_back(a + (b - a) * i / (c.samples - 1));
  } else {
    for (double xi : c.runs.front().x) {
      if (xi >= a && xi <= b) x.push_back(xi);
    }
  }
  if (x.size() < 2) {
    f.fail("measurements", fmt::format("{} measured point(s) in the common range {:g} .. {:g} mm; "
                                       "at least 2 needed (or set samples)",
                                       x.size(), 1e3 * a, 1e3 * b));
  }
  return x;
}

FitCurve read_curve(const Fields& c, const std::string& default_scene, const std::string& file) {
  FitCurve fc;
  if (c.has("scene")) {
    fc.scene = path_beside(file, c.required_word("scene"));
  } else if (default_scene.empty()) {
    c.fail("scene", "required here when the fit file has no top-level scene");
  } else {
    fc.scene = default_scene;
  }
  if (!fs::exists(fc.scene)) c.fail("scene", "no such file: " + fc.scene);
  for (const std::string& s : c.has("set") ? c.words("set") : std::vector<std::string>{}) {
    try {
      fc.set.push_back(parse_override(s));
    } catch (const InputError& e) {
      c.fail("set", fmt::format("'{}': {}", s, e.what()));
    }
  }
  fc.probe = c.word("probe", "");
  std::vector<std::string> columns =
      c.has("columns") ? c.words("columns") : std::vector<std::string>{};
  if (!columns.empty() && columns.size() != 2) {
    c.fail("columns", "two column names: [displacement, force]");
  }
  columns.resize(2);
  const std::vector<std::string> files = c.words("measurements");
  if (files.empty()) c.fail("measurements", "at least one measurement file");
  for (const std::string& m : files) {
    fc.runs.push_back(read_force_curve(path_beside(file, m), columns[0], columns[1]));
  }
  if (c.has("window_mm")) {
    const std::vector<double> w = c.numbers("window_mm", any_finite("mm"));
    if (w.size() != 2 || !(w[1] > w[0])) c.fail("window_mm", "[min, max] in mm with max > min");
    fc.window = {1e-3 * w[0], 1e-3 * w[1]};
  }
  fc.samples = c.integer("samples", 0, 0, 100000);
  if (fc.samples == 1) c.fail("samples", "0 (the measured displacements) or 2 .. 100000");
  fc.x = curve_grid(fc, c);
  return fc;
}

FitSolverSettings read_solver(const Fields& s) {
  FitSolverSettings o;
  o.max_iterations = s.integer("max_iterations", o.max_iterations, 1, 1000);
  o.relative_step = s.number("relative_step", o.relative_step, interval(1e-8, 0.1, false, false));
  const Range unit = interval(0, 1, true, true);
  o.function_tolerance = s.number("function_tolerance", o.function_tolerance, unit);
  o.parameter_tolerance = s.number("parameter_tolerance", o.parameter_tolerance, unit);
  o.gradient_tolerance = s.number("gradient_tolerance", o.gradient_tolerance, unit);
  return o;
}

}  // namespace

FitSpec read_fit(const std::string& path) {
  const Fields f = read_fields_file(path, {"scene", "curves", "parameters", "solver"});
  FitSpec s;
  s.file = path;
  const std::string scene = f.has("scene") ? path_beside(path, f.required_word("scene")) : "";
  const auto params = sequence(f.node("parameters"), f.context("parameters"), "parameters");
  if (params.empty()) f.fail("parameters", "at least one parameter");
  std::set<std::string> paths;
  for (std::size_t i = 0; i < params.size(); ++i) {
    const Fields p(params[i], {path, item_field("parameters", i)},
                   {"path", "initial", "lower", "upper", "scale"});
    s.parameters.push_back(read_parameter(p));
    for (const std::string& q : s.parameters.back().paths) {
      if (!paths.insert(q).second) p.fail("path", q + " is fitted twice");
    }
  }
  const auto curves = sequence(f.node("curves"), f.context("curves"), "curves");
  if (curves.empty()) f.fail("curves", "at least one measured curve");
  std::size_t residuals = 0;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const Fields c(curves[i], {path, item_field("curves", i)},
                   {"scene", "set", "probe", "measurements", "columns", "window_mm", "samples"});
    s.curves.push_back(read_curve(c, scene, path));
    residuals += s.curves.back().x.size();
  }
  if (residuals <= s.parameters.size()) {
    f.fail("curves", fmt::format("{} measured points for {} parameters: need more points than "
                                 "parameters (standard errors divide by their difference)",
                                 residuals, s.parameters.size()));
  }
  if (f.has("solver")) {
    s.solver = read_solver(Fields(f.node("solver"), f.context("solver"),
                                  {"max_iterations", "relative_step", "function_tolerance",
                                   "parameter_tolerance", "gradient_tolerance"}));
  }
  return s;
}

}  // namespace finseg
