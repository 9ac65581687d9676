// finseg identify bending|crease DATA: stiffness identification from the paper's tests
// (section 3). docs/crease-data.md describes the files and the formulas.
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>

#include "apps/finseg/commands.hpp"
#include "core/error.hpp"
#include "identification/bending.hpp"
#include "identification/crease.hpp"
#include "writers/atomic_write.hpp"
#include "writers/plot.hpp"

namespace finseg::cli {

namespace {

struct BendingOptions {
  std::string data, out;
  std::optional<double> length, width, thickness;
  int segments = 16;
};

struct CreaseOptions {
  std::string data, out = "creases.csv", plot, ends = "not-a-knot";
  std::optional<double> lever;
  bool no_plot = false;
};

std::optional<double> pick(const std::optional<double>& option, const std::optional<double>& file,
                           const char* name, const std::string& source) {
  if (option && file && *option != *file) {
    fmt::print(stderr, "finseg: note: --{} {} m overrides {} m from {}\n", name, *option, *file,
               source);
  }
  return option ? option : file;
}

void run_bending(const BendingOptions& o) {
  const CantileverData d = read_cantilever_data(o.data);
  const std::optional<double> L = pick(o.length, d.length, "length", d.source);
  if (!L) {
    throw InputError(o.data, "length_m",
                     "free length unknown: give '# length_m: ...' in the file or --length");
  }
  const auto width = pick(o.width, d.width, "width", d.source);
  const auto thickness = pick(o.thickness, d.thickness, "thickness", d.source);
  const BendingIdentification r = identify_bending(d, *L, o.segments, width, thickness);
  fmt::print("cantilever {}: {} points, compliance x/F = {:.6g} m/N (rms residual {:.3g} m)\n",
             d.source, d.force.size(), r.compliance, r.rms_residual);
  if (r.max_slope > 0.1) {
    fmt::print(stderr,
               "finseg: warning: largest tip displacement is {:.3g} L; small-deflection theory "
               "(paper 3.1) loses accuracy beyond about 0.1 L\n",
               r.max_slope);
  }
  fmt::print("continuum EI = L^3/(3c)            = {:.6g} N m^2\n", r.EI_continuum);
  fmt::print("chain of {} cells (h = {:.6g} m): EI = {:.6g} N m^2 (factor 1 - 1/(4N^2) = {:.8f})\n",
             r.segments, r.cell_length, r.EI_chain, chain_compliance_factor(r.segments));
  fmt::print("joint bending stiffness k = EI/h    = {:.6g} N m/rad\n", r.joint_stiffness);
  if (r.youngs_modulus)
    fmt::print("Young's modulus 12 EI/(b t^3)     = {:.6g} Pa\n", *r.youngs_modulus);
  if (!o.out.empty()) {
    std::string yaml = fmt::format(
        "# finseg identify bending {}: tip compliance x/F = {:.9g} m/N, free length {:.9g} m\n"
        "# continuum EI = L^3/(3c) = {:.9g} N m^2; joint stiffness k = EI_chain/h = {:.9g} N "
        "m/rad\n",
        d.source, r.compliance, r.length, r.EI_continuum, r.joint_stiffness);
    if (r.youngs_modulus)
      yaml += fmt::format("# Young's modulus 12 EI/(b t^3) = {:.9g} Pa\n", *r.youngs_modulus);
    yaml += fmt::format(
        "# Scene fragment (docs/scene.md, `stiffness`): EI_chain reproduces the measured\n"
        "# compliance with {} cells along the free length (docs/crease-data.md).\n"
        "stiffness:\n"
        "  bending_rigidity: {:.17g}   # N m^2 (EI_chain, {} cells)\n",
        r.segments, r.EI_chain, r.segments);
    write_file_atomically(o.out, yaml);
    fmt::print("wrote {} (scene fragment: stiffness.bending_rigidity)\n", o.out);
  }
}

void run_crease(const CreaseOptions& o) {
  SplineEnds ends;
  if (!parse_spline_ends(o.ends, ends)) {
    throw InputError("<cli>", "--ends", fmt::format("'{}'; allowed: natural, not-a-knot", o.ends));
  }
  const CreaseData flap = read_crease_data(o.data, o.lever);
  const CreaseIdentification id = identify_crease(flap, ends);
  fmt::print("flap test {}: {} curve(s), {} ends\n", flap.source, id.curves.size(), o.ends);
  fmt::print("{:>10} {:>7} {:>6} {:>7} {:>15} {:>9} {:>14} {:>14} {:>14}\n", "pressed_s", "opening",
             "points", "repeats", "range_deg", "rest_deg", "K_secant", "dM/dth_start",
             "dM/dth_end");
  for (const CreaseCurveSummary& s : id.curves) {
    fmt::print(
        "{:>10.6g} {:>7} {:>6} {:>7} {:>7.4g}..{:<7.4g} {:>9.4g} {:>14.6g} {:>14.6g} {:>14.6g}\n",
        s.pressing_time, s.opening, s.points, s.repeats, s.theta_min_deg, s.theta_max_deg,
        s.rest_deg, s.secant_stiffness, s.tangent_start, s.tangent_end);
  }
  fmt::print("(stiffnesses in N m/rad; angles are opening angles, 0 = folded shut)\n");
  write_crease_data(o.out, id.data,
                    {fmt::format("crease law identified by finseg from {} (M = F L, repeats "
                                 "averaged)",
                                 flap.source),
                     "angle_deg: opening angle (0 = folded flat shut, 180 = flat); moment_Nm: "
                     "moment holding the crease open"});
  fmt::print("wrote {}\n", o.out);
  if (!o.no_plot) {
    const std::string plot = o.plot.empty() ? o.out + ".svg" : o.plot;
    write_plot(plot, crease_plot(id, ends));
    fmt::print("wrote {}\n", plot);
  }
}

}  // namespace

void register_identify(CLI::App& app) {
  CLI::App* id = app.add_subcommand("identify", "identify stiffness from test data (paper sec. 3)");
  id->require_subcommand(1);

  auto b = std::make_shared<BendingOptions>();
  CLI::App* bend = id->add_subcommand(
      "bending", "cantilever test (force_N, tip_displacement_m) -> EI and joint stiffness");
  bend->add_option("DATA", b->data, "cantilever CSV")->required()->check(CLI::ExistingFile);
  bend->add_option("--length", b->length, "free length clamp to load, m (or '# length_m:')");
  bend->add_option("--width", b->width, "strip width, m (for Young's modulus)");
  bend->add_option("--thickness", b->thickness, "strip thickness, m (for Young's modulus)");
  bend->add_option("--segments", b->segments, "cells N of the model's cantilever")
      ->check(CLI::Range(1, 1000000));
  bend->add_option("--out", b->out,
                   "write a scene fragment (stiffness: bending_rigidity: EI_chain) to FILE");
  bend->callback([b] { run_bending(*b); });

  auto c = std::make_shared<CreaseOptions>();
  CLI::App* cr = id->add_subcommand(
      "crease", "flap test (angle_deg, force_N, lever_m, ...) -> crease data file + plot");
  cr->add_option("DATA", c->data, "flap-test CSV (docs/crease-data.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cr->add_option("--lever", c->lever, "lever L, m, when the file has no lever_m column");
  cr->add_option("--ends", c->ends, "spline ends: natural | not-a-knot");
  cr->add_option("--out", c->out, "crease data file to write");
  cr->add_option("--plot", c->plot, "plot file (.svg or .png; default OUT.svg)");
  cr->add_flag("--no-plot", c->no_plot, "skip the plot");
  cr->callback([c] { run_crease(*c); });
}

}  // namespace finseg::cli
