#include "py_generators.hpp"

#include <fmt/format.h>

#include <functional>
#include <map>

#include "core/error.hpp"
#include "scene/gen_options.hpp"

namespace finseg::py {

namespace pyb = pybind11;

namespace {

const OptionNaming kPythonNames{"<python>", "", '_'};

[[noreturn]] void wrong_type(const std::string& name, const std::string& expected,
                             const pyb::handle& v) {
  throw InputError(
      kPythonNames.source, name,
      fmt::format("{}; expected {}", pyb::str(pyb::repr(v)).cast<std::string>(), expected));
}

double number(const pyb::handle& v, const std::string& name, const char* unit) {
  if (!pyb::isinstance<pyb::bool_>(v) &&
      (pyb::isinstance<pyb::float_>(v) || pyb::isinstance<pyb::int_>(v))) {
    return v.cast<double>();
  }
  wrong_type(name, fmt::format("a number, {}", unit), v);
}

int integer(const pyb::handle& v, const std::string& name) {
  if (!pyb::isinstance<pyb::bool_>(v) && pyb::isinstance<pyb::int_>(v)) {
    try {
      return v.cast<int>();
    } catch (const pyb::cast_error&) {
    }
  }
  wrong_type(name, "an integer", v);
}

bool flag(const pyb::handle& v, const std::string& name) {
  if (!pyb::isinstance<pyb::bool_>(v)) wrong_type(name, "True or False", v);
  return v.cast<bool>();
}

std::string text(const pyb::handle& v, const std::string& name) {
  if (!pyb::isinstance<pyb::str>(v)) wrong_type(name, "a string", v);
  return v.cast<std::string>();
}

std::vector<pyb::handle> items(const pyb::handle& v, const std::string& name, const char* what) {
  if (!pyb::isinstance<pyb::list>(v) && !pyb::isinstance<pyb::tuple>(v)) wrong_type(name, what, v);
  std::vector<pyb::handle> out;
  for (const pyb::handle& x : v) out.push_back(x);
  return out;
}

Vec3 vec3(const pyb::handle& v, const std::string& name, const char* unit) {
  const auto xs = items(v, name, "three numbers (x, y, z)");
  if (xs.size() != 3) wrong_type(name, "three numbers (x, y, z)", v);
  return {number(xs[0], name, unit), number(xs[1], name, unit), number(xs[2], name, unit)};
}

std::vector<int> integers(const pyb::handle& v, const std::string& name) {
  std::vector<int> out;
  for (const pyb::handle& x : items(v, name, "a list of integers")) out.push_back(integer(x, name));
  return out;
}

template <class O>
using Setter = std::function<void(O&, const pyb::handle&, const std::string&)>;

// Applies every keyword argument through `table`; an unknown one lists the allowed names.
template <class O>
void apply(O& o, const pyb::kwargs& options, const std::map<std::string, Setter<O>>& table) {
  for (const auto& [key, value] : options) {
    const std::string name = pyb::str(key).cast<std::string>();
    const auto it = table.find(name);
    if (it == table.end()) {
      std::string allowed;
      for (const auto& [k, s] : table) allowed += (allowed.empty() ? "" : ", ") + k;
      throw InputError(kPythonNames.source, name, "unknown option; allowed: " + allowed);
    }
    it->second(o, value, name);
  }
}

// The solver options both generators take (`finseg gen ... --solver --t-end --dt ...`).
template <class O>
void add_solver_options(std::map<std::string, Setter<O>>& t, SolverSettings O::*solver) {
  t["solver"] = [solver](O& o, const pyb::handle& v, const std::string& n) {
    const auto kind = solver_kind_from_name(text(v, n));
    if (!kind) wrong_type(n, "'static', 'implicit' or 'explicit'", v);
    (o.*solver).kind = *kind;
  };
  t["t_end"] = [solver](O& o, const pyb::handle& v, const std::string& n) {
    (o.*solver).t_end = number(v, n, "s");
  };
  t["dt"] = [solver](O& o, const pyb::handle& v, const std::string& n) {
    (o.*solver).dt = number(v, n, "s");
  };
  t["output_interval"] = [solver](O& o, const pyb::handle& v, const std::string& n) {
    (o.*solver).output_interval = number(v, n, "s");
  };
  t["load_steps"] = [solver](O& o, const pyb::handle& v, const std::string& n) {
    (o.*solver).load_steps = integer(v, n);
  };
}

// A setter of a double member reached through `part` (e.g. the spec inside the options).
template <class O, class P>
Setter<O> num(P O::*part, double P::*field, const char* unit) {
  return [=](O& o, const pyb::handle& v, const std::string& n) {
    (o.*part).*field = number(v, n, unit);
  };
}

template <class O, class P>
Setter<O> whole(P O::*part, int P::*field) {
  return
      [=](O& o, const pyb::handle& v, const std::string& n) { (o.*part).*field = integer(v, n); };
}

struct CantileverGen {
  CantileverSpec spec;
  SolverSettings solver;
};

}  // namespace

std::string cantilever_text(const pyb::kwargs& options) {
  using O = CantileverGen;
  using S = CantileverSpec;
  const auto s = &O::spec;
  std::map<std::string, Setter<O>> t{
      {"length", num(s, &S::length, "m")},
      {"width", num(s, &S::width, "m")},
      {"thickness", num(s, &S::thickness, "m")},
      {"modulus", num(s, &S::youngs_modulus, "Pa")},
      {"poisson", num(s, &S::poisson_ratio, "-")},
      {"density", num(s, &S::density, "kg/m^3")},
      {"segments", whole(s, &S::segments)},
      {"segments_across", whole(s, &S::segments_across)},
      {"damping_time", num(s, &S::damping_time, "s")},
      {"tip_force", [](O& o, const pyb::handle& v,
                       const std::string& n) { o.spec.tip_force = vec3(v, n, "N"); }},
      {"tip_moment", [](O& o, const pyb::handle& v,
                        const std::string& n) { o.spec.tip_moment = vec3(v, n, "N m"); }},
      {"gravity",
       [](O& o, const pyb::handle& v, const std::string& n) { o.spec.gravity = flag(v, n); }},
  };
  add_solver_options(t, &O::solver);
  O o;
  apply(o, options, t);
  return cantilever_gen_scene(o.spec, o.solver, kPythonNames);
}

std::string zigzag_text(const pyb::kwargs& options) {
  using O = ZigzagGenOptions;
  using Z = ZigzagSceneOptions;
  using S = ZigzagSpec;
  // Fields of the spec (two levels down) need their own small setters.
  const auto spec_num = [](double S::*field, const char* unit) -> Setter<O> {
    return [=](O& o, const pyb::handle& v, const std::string& n) {
      o.z.spec.*field = number(v, n, unit);
    };
  };
  const auto spec_int = [](int S::*field) -> Setter<O> {
    return
        [=](O& o, const pyb::handle& v, const std::string& n) { o.z.spec.*field = integer(v, n); };
  };
  const auto opt_num = [](std::optional<double> Z::*field, const char* unit) -> Setter<O> {
    return
        [=](O& o, const pyb::handle& v, const std::string& n) { o.z.*field = number(v, n, unit); };
  };
  std::map<std::string, Setter<O>> t{
      {"length", spec_num(&S::length, "m")},
      {"width", spec_num(&S::width, "m")},
      {"thickness", spec_num(&S::thickness, "m")},
      {"modulus", spec_num(&S::youngs_modulus, "Pa")},
      {"poisson", spec_num(&S::poisson_ratio, "-")},
      {"density", spec_num(&S::density, "kg/m^3")},
      {"panels", spec_int(&S::panels)},
      {"fold_angle", num(&O::z, &Z::fold_angle_deg, "deg")},
      {"pattern",
       [](O& o, const pyb::handle& v, const std::string& n) { o.z.spec.pattern = text(v, n); }},
      {"segments_per_panel", spec_int(&S::segments_per_panel)},
      {"segments_across", spec_int(&S::segments_across)},
      {"refinement", spec_num(&S::crease_refinement, "-")},
      {"fixed_panels", [](O& o, const pyb::handle& v,
                          const std::string& n) { o.z.spec.fixed_panels = integers(v, n); }},
      {"pulled_crease", spec_int(&S::pulled_crease)},
      {"pull_step", spec_num(&S::pull_step, "m")},
      {"pull_travel", spec_num(&S::pull_travel, "m")},
      {"gauge_stiffness", spec_num(&S::gauge_stiffness, "N/m")},
      {"pull_speed", opt_num(&Z::pull_speed, "m/s")},
      {"crease_law",
       [](O& o, const pyb::handle& v, const std::string& n) { o.z.crease_law_file = text(v, n); }},
      {"pressing_time", opt_num(&Z::pressing_time, "s")},
      {"crease_stiffness", opt_num(&Z::crease_stiffness, "N m/rad")},
      {"bending_rigidity",
       [](O& o, const pyb::handle& v, const std::string& n) {
         o.z.spec.overrides.bending_rigidity = number(v, n, "N m^2");
       }},
      {"damping_time", spec_num(&S::damping_time, "s")},
      {"gravity",
       [](O& o, const pyb::handle& v, const std::string& n) { o.z.spec.gravity = flag(v, n); }},
      {"contact",
       [](O& o, const pyb::handle& v, const std::string& n) { o.z.spec.contact = flag(v, n); }},
  };
  add_solver_options(t, &O::solver);
  const Setter<O> t_end = t["t_end"];
  t["t_end"] = [t_end](O& o, const pyb::handle& v, const std::string& n) {
    t_end(o, v, n);
    o.t_end_given = true;
  };
  O o;
  apply(o, options, t);
  return zigzag_gen_scene(o, kPythonNames);
}

}  // namespace finseg::py
