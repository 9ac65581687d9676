// finseg gen cantilever|zigzag [options] [--out FILE]: writes a scene file (stdout or FILE,
// atomically) that `finseg run` reads back to the model the generators build.
#include <fmt/format.h>

#include <memory>
#include <sstream>
#include <string>

#include "apps/finseg/commands.hpp"
#include "core/error.hpp"
#include "scene/gen_options.hpp"
#include "writers/atomic_write.hpp"

namespace finseg::cli {

namespace {

struct SolverOptions {
  std::string kind = "static", out;
  SolverSettings settings;
};

struct CantileverOptions : SolverOptions {
  CantileverSpec spec;
  std::string tip_force = "0,0,0", tip_moment = "0,0,0";
};

struct ZigzagOptions : SolverOptions {
  ZigzagSceneOptions z;
  std::string fixed_panels = "1,6";
  std::optional<double> bending_rigidity;
  bool no_gravity = false, no_contact = false;
};

Vec3 parse_vec3(const std::string& text, const char* option, const char* unit) {
  std::stringstream in(text);
  Vec3 v;
  char comma = 0;
  if (!(in >> v.x() >> comma) || comma != ',' || !(in >> v.y() >> comma) || comma != ',' ||
      !(in >> v.z()) || !(in >> std::ws).eof() || !v.allFinite()) {
    throw InputError("<cli>", option,
                     fmt::format("'{}'; expected three finite numbers X,Y,Z ({})", text, unit));
  }
  return v;
}

std::vector<int> parse_ints(const std::string& text, const char* option) {
  std::vector<int> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    try {
      std::size_t used = 0;
      out.push_back(std::stoi(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError("<cli>", option, fmt::format("'{}'; expected integers like 1,6", text));
    }
  }
  return out;
}

void apply_solver(SolverOptions& o) {
  o.settings.kind = solver_kind_from_name(o.kind).value_or(SolverKind::Static);
}

void emit(const std::string& out, const std::string& yaml) {
  if (out.empty()) {
    fmt::print("{}", yaml);
  } else {
    write_file_atomically(out, yaml);
    fmt::print(stderr, "wrote {}\n", out);
  }
}

void add_solver_options(CLI::App* cmd, SolverOptions& o) {
  cmd->add_option("--solver", o.kind, "static | implicit | explicit")
      ->check(CLI::IsMember({"static", "implicit", "explicit"}));
  cmd->add_option("--t-end", o.settings.t_end, "simulated time of dynamic solvers, s");
  cmd->add_option("--dt", o.settings.dt, "time step, s (explicit: fixed, 0 automatic)");
  cmd->add_option("--output-interval", o.settings.output_interval,
                  "s between outputs (0: t_end/100)");
  cmd->add_option("--load-steps", o.settings.load_steps, "static: initial load increments");
  cmd->add_option("--out", o.out, "write the scene to FILE instead of standard output");
}

void register_cantilever(CLI::App* gen) {
  auto o = std::make_shared<CantileverOptions>();
  CLI::App* c = gen->add_subcommand(
      "cantilever", "strip clamped at x = 0 along +x, tip load (paper 3.1 bending test)");
  CantileverSpec& s = o->spec;
  c->add_option("--length", s.length, "free length clamp to tip, m");
  c->add_option("--width", s.width, "width along y, m");
  c->add_option("--thickness", s.thickness, "m");
  c->add_option("--modulus", s.youngs_modulus, "Young's modulus, Pa");
  c->add_option("--poisson", s.poisson_ratio, "Poisson ratio");
  c->add_option("--density", s.density, "kg/m^3");
  c->add_option("--segments", s.segments, "segments along the length");
  c->add_option("--segments-across", s.segments_across, "segments across the width");
  c->add_option("--tip-force", o->tip_force, "dead tip load FX,FY,FZ, N");
  c->add_option("--tip-moment", o->tip_moment, "dead tip moment MX,MY,MZ, N m");
  c->add_flag("--gravity", s.gravity, "gravity 9.81 m/s^2 along -z");
  c->add_option("--damping-time", s.damping_time, "element damping C = time * K, s");
  add_solver_options(c, *o);
  c->callback([o] {
    o->spec.tip_force = parse_vec3(o->tip_force, "--tip-force", "N");
    o->spec.tip_moment = parse_vec3(o->tip_moment, "--tip-moment", "N m");
    apply_solver(*o);
    emit(o->out, cantilever_gen_scene(o->spec, o->settings, kCliNames));
  });
}

void register_zigzag(CLI::App* gen) {
  auto o = std::make_shared<ZigzagOptions>();
  CLI::App* c = gen->add_subcommand(
      "zigzag", "strip folded into panels, a crease pulled open (paper section 4)");
  ZigzagSpec& s = o->z.spec;
  c->add_option("--length", s.length, "whole strip, m");
  c->add_option("--width", s.width, "m");
  c->add_option("--thickness", s.thickness, "m");
  c->add_option("--modulus", s.youngs_modulus, "Young's modulus, Pa");
  c->add_option("--poisson", s.poisson_ratio, "Poisson ratio");
  c->add_option("--density", s.density, "kg/m^3");
  c->add_option("--panels", s.panels, "number of panels");
  c->add_option("--fold-angle", o->z.fold_angle_deg, "angle panel/horizontal, deg");
  c->add_option("--pattern", s.pattern, "P/V per crease, e.g. PVPVP (default: alternate)");
  c->add_option("--segments-per-panel", s.segments_per_panel, "segments along each panel");
  c->add_option("--segments-across", s.segments_across, "segments across the width");
  c->add_option("--refinement", s.crease_refinement, "middle cell / cell at a crease");
  c->add_option("--fixed-panels", o->fixed_panels, "clamped panels, 1-based, e.g. 1,6");
  c->add_option("--pulled-crease", s.pulled_crease, "crease pulled, 1-based");
  c->add_option("--pull-step", s.pull_step, "m per equilibrium");
  c->add_option("--pull-travel", s.pull_travel, "m (0: default)");
  c->add_option("--gauge-stiffness", s.gauge_stiffness, "N/m");
  c->add_option("--pull-speed", o->z.pull_speed,
                "m/s: dynamic solvers pull at this speed (default: the travel in 1 s); "
                "without --t-end, t_end = travel / speed");
  c->add_option("--crease-law", o->z.crease_law_file, "measured crease data file for all creases")
      ->check(CLI::ExistingFile);
  c->add_option("--pressing-time", o->z.pressing_time,
                "s: pressing time of the --crease-law curves to use (interpolated)");
  c->add_option("--crease-stiffness", o->z.crease_stiffness,
                "linear crease stiffness, N m/rad (resting at the fold)");
  c->add_option("--bending-rigidity", o->bending_rigidity, "EI of the whole width, N m^2");
  c->add_option("--damping-time", s.damping_time, "element damping C = time * K, s");
  c->add_flag("--no-gravity", o->no_gravity, "no gravity");
  c->add_flag("--no-contact", o->no_contact, "no contact between panels");
  add_solver_options(c, *o);
  c->callback([o, c] {
    ZigzagSpec& spec = o->z.spec;
    spec.fixed_panels = parse_ints(o->fixed_panels, "--fixed-panels");
    spec.overrides.bending_rigidity = o->bending_rigidity;
    spec.gravity = !o->no_gravity;
    spec.contact = !o->no_contact;
    apply_solver(*o);
    emit(o->out, zigzag_gen_scene({o->z, o->settings, c->count("--t-end") > 0}, kCliNames, o->out));
  });
}

}  // namespace

void register_gen(CLI::App& app) {
  CLI::App* gen = app.add_subcommand("gen", "write a scene file from a generator");
  gen->require_subcommand(1);
  register_cantilever(gen);
  register_zigzag(gen);
  register_pattern_generators(gen);
}

}  // namespace finseg::cli
