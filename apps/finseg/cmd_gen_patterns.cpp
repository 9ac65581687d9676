// finseg gen miura|cone [options] --out SCENE.yaml: writes a crease pattern (SCENE.fold,
// docs/fold.md) and a scene that cuts the sheet from it, folds it (`finseg run --fold`,
// docs/folding.md) and pulls it open.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include "apps/finseg/commands.hpp"
#include "core/error.hpp"
#include "core/rigid_fit.hpp"
#include "core/text.hpp"
#include "model/segment_shape.hpp"
#include "patterns/cone_pattern.hpp"
#include "patterns/fold_format.hpp"
#include "patterns/miura_pattern.hpp"
#include "patterns/pattern_checks.hpp"
#include "scene/gen_options.hpp"
#include "scene/scene_parts.hpp"
#include "writers/atomic_write.hpp"

namespace finseg::cli {

namespace {

namespace fs = std::filesystem;

/// What both generated scenes share: material, discretisation and crease stiffness.
struct SheetOptions {
  std::string out;
  double thickness = 1e-4, modulus = 3e9, density = 800, crease_stiffness = 0.05;
  int subdivisions = 2;
  double segment_size = 0, crease_refinement = 1;  // m (0: by subdivisions), ratio
  std::string cells = "quadrilaterals";            // or triangles (pattern.cells)
  CLI::Option* subdivisions_option = nullptr;
};

void add_sheet_options(CLI::App* c, SheetOptions& o) {
  c->add_option("--thickness", o.thickness, "m")->capture_default_str();
  c->add_option("--modulus", o.modulus, "Young's modulus, Pa")->capture_default_str();
  c->add_option("--density", o.density, "kg/m^3")->capture_default_str();
  c->add_option("--crease-stiffness", o.crease_stiffness,
                "linear crease stiffness per metre of crease, N m/rad/m (resting folded)")
      ->capture_default_str();
  o.subdivisions_option =
      c->add_option("--subdivisions", o.subdivisions, "each face into n x n segments")
          ->capture_default_str();
  c->add_option("--segment-size", o.segment_size,
                "m: segments of at most this side along every crease, in place of "
                "--subdivisions (docs/fold.md, Segments)");
  c->add_option("--crease-refinement", o.crease_refinement,
                "segments graded towards the folds: the one at a fold 1/this of the middle one")
      ->capture_default_str();
  c->add_option("--cells", o.cells,
                "quadrilaterals, or triangles: each segment cut into four triangles, which bend "
                "where quadrilaterals lock (docs/fold.md, Triangle cells)")
      ->capture_default_str();
  c->add_option("--out", o.out, "scene file to write; the pattern goes beside it as .fold")
      ->required();
}

void check_sheet(const SheetOptions& o) {
  require_positive(o.thickness, "<cli>", "--thickness", "m");
  require_positive(o.modulus, "<cli>", "--modulus", "Pa");
  require_positive(o.density, "<cli>", "--density", "kg/m^3");
  require_positive(o.crease_stiffness, "<cli>", "--crease-stiffness", "N m/rad/m");
  if (o.subdivisions < 1 || o.subdivisions > 64) {
    throw InputError("<cli>", "--subdivisions",
                     fmt::format("{}; allowed range 1..64", o.subdivisions));
  }
  if (o.segment_size != 0) {
    require_positive(o.segment_size, "<cli>", "--segment-size", "m");
    if (o.subdivisions_option != nullptr && o.subdivisions_option->count() > 0) {
      throw InputError("<cli>", "--segment-size", "give either --subdivisions or --segment-size");
    }
  }
  if (!(o.crease_refinement >= 1 && o.crease_refinement <= 100)) {
    throw InputError("<cli>", "--crease-refinement",
                     fmt::format("{}; allowed range [1, 100]", o.crease_refinement));
  }
  if (o.cells != "quadrilaterals" && o.cells != "triangles") {
    throw InputError("<cli>", "--cells",
                     fmt::format("'{}'; allowed: quadrilaterals, triangles", o.cells));
  }
}

// The pattern section's discretisation lines.
std::string discretisation_lines(const SheetOptions& o) {
  std::string s = o.segment_size > 0 ? fmt::format("  segment_size: {:g}\n", o.segment_size)
                                     : fmt::format("  subdivisions: {}\n", o.subdivisions);
  if (o.crease_refinement != 1)
    s += fmt::format("  crease_refinement: {:g}\n", o.crease_refinement);
  if (o.cells != "quadrilaterals") s += fmt::format("  cells: {}\n", o.cells);
  return s;
}

// The scene's material, sheet and pattern sections (laws resting at the pattern's angles);
// `damping_time` (s) > 0 adds the material's stiffness-proportional damping.
std::string sheet_sections(const SheetOptions& o, const std::string& fold_file,
                           double damping_time = 0) {
  const std::string damping =
      damping_time > 0 ? fmt::format(", damping_time: {:g}", damping_time) : "";
  return fmt::format(
      "material: {{youngs_modulus: {:g}, poisson_ratio: 0.3, density: {:g}{}}}\n"
      "sheet: {{thickness: {:g}}}\n"
      "pattern:\n"
      "  file: {}\n"
      "{}"
      "  start: folded            # the pattern's folded coordinates\n"
      "  crease_rest: pattern     # each crease rests at its edges_foldAngle\n"
      "  crease_law_length: 1.0   # laws below are per metre of crease\n"
      "  mountain_law: {{type: linear, stiffness: {:g}, rest_angle_deg: 0}}\n"
      "  valley_law: {{type: linear, stiffness: {:g}, rest_angle_deg: 0}}\n",
      o.modulus, o.density, damping, o.thickness, fold_file, discretisation_lines(o),
      o.crease_stiffness, o.crease_stiffness);
}

// Writes the pattern beside the scene and the scene itself (both atomically).
void write_pair(const SheetOptions& o, const CreasePattern& p, const std::string& scene_body) {
  const fs::path scene = o.out;
  fs::path fold = scene;
  fold.replace_extension(".fold");
  write_fold(fold.string(), p);
  write_file_atomically(scene.string(), scene_body);
  fmt::print(stderr, "wrote {} and {}\n", scene.string(), fold.string());
}

Vec2 face_centroid(const CreasePattern& p, int face) {
  Outline o;
  for (int v : p.faces[face]) o.push_back(p.vertices_flat_m[v]);
  return polygon_centroid(o);
}

void register_miura(CLI::App* gen) {
  auto o = std::make_shared<SheetOptions>();
  auto s = std::make_shared<MiuraSpec>();
  auto angles = std::make_shared<std::pair<double, double>>(60.0, 70.0);
  CLI::App* c = gen->add_subcommand("miura", "Miura-ori sheet, folded, pulled open along x");
  c->add_option("--rows", s->rows, "parallelograms along y (a sides)")->capture_default_str();
  c->add_option("--columns", s->columns, "parallelograms along x (b sides)")->capture_default_str();
  c->add_option("--side-a", s->side_a, "m")->capture_default_str();
  c->add_option("--side-b", s->side_b, "m")->capture_default_str();
  c->add_option("--sector-angle", angles->first, "parallelogram's acute angle, deg (0, 90)")
      ->capture_default_str();
  c->add_option("--fold-angle", angles->second, "panels to the plane when folded, deg [0, 90)")
      ->capture_default_str();
  add_sheet_options(c, *o);
  c->callback([o, s, angles] {
    check_sheet(*o);
    if (!(angles->second > 0)) {  // (the pattern alone may be flat: `finseg pattern miura`)
      throw InputError("<cli>", "--fold-angle",
                       fmt::format("{} deg; allowed (0, 90): the scene folds the sheet and pulls "
                                   "it open",
                                   angles->second));
    }
    s->sector_angle = angles->first * kDegToRad;
    s->fold_angle = angles->second * kDegToRad;
    CreasePattern p;
    in_scene_file(
        "<cli>", [&] { p = miura_crease_pattern(*s); }, kCliNames);
    // Face 1 (row 0, column 0) clamped; the last column's first face pulled along +x until
    // the sheet is open to 15 degrees (a sheet folded less: to half its fold angle).
    const Vec2 pulled = face_centroid(p, s->columns - 1);
    // Along the first row's crease line (x of Schenk and Guest's frame): two columns on.
    const Vec3 along = s->columns >= 2
                           ? (p.vertices_folded_m[2] - p.vertices_folded_m[0]).normalized()
                           : Vec3(p.vertices_folded_m[1] - p.vertices_folded_m[0]).normalized();
    const double open_to = std::min(15 * kDegToRad, 0.5 * s->fold_angle);
    const double travel =
        (s->columns - 1) * (miura_cell(*s, open_to).S - miura_cell(*s, s->fold_angle).S);
    const std::string fold_file = fs::path(o->out).replace_extension(".fold").filename();
    const std::string yaml = fmt::format(
        "# finseg gen miura: {} x {} parallelograms {:g} x {:g} m, sector angle {:g} deg, folded "
        "to {:g} deg.\n"
        "# Run: finseg run {} --out DIR (pull open from the pattern's folded form), or fold the\n"
        "# flat sheet first: finseg run {} --fold --set pattern.start=flat --out F, then\n"
        "# finseg run {} --state F/checkpoint.json --out DIR (docs/folding.md).\n"
        "title: Miura-ori {} x {} pulled open\n{}"
        "fixtures: {{panels: [1]}}\n"
        "folding:\n"
        "  fraction: 1.0\n"
        "  solver: {{type: static, load_steps: 20}}\n"
        "drives:\n"
        "  - {{name: pull, at: {{s: {:.9g}, y: {:.9g}}}, direction: [{:.9g}, {:.9g}, {:.9g}],\n"
        "     stiffness: 100, travel: {:.6g}, step: {:.6g}}}\n"
        "probes:\n"
        "  - {{name: pull, type: drive, drive: pull}}\n"
        "  - {{name: energy, type: energy}}\n"
        "solver: {{type: static}}\n",
        s->rows, s->columns, s->side_a, s->side_b, angles->first, angles->second,
        fs::path(o->out).filename().string(), fs::path(o->out).filename().string(),
        fs::path(o->out).filename().string(), s->rows, s->columns, sheet_sections(*o, fold_file),
        pulled.x(), pulled.y(), along.x(), along.y(), along.z(), travel, travel / 40);
    write_pair(*o, p, yaml);
  });
}

Vec3 folded_centroid(const std::vector<Vec3>& x, const std::vector<int>& face) {
  Vec3 c = Vec3::Zero();
  for (int v : face) c += x[v];
  return c / static_cast<double>(face.size());
}

// The wall gathered (cone_gathered), each crease's fold angle that of the gathered state (so
// that it rests there with `crease_rest: pattern`): a generator's as measured where it agrees
// with its kind, else 0, the rings' 0 (flat).
void gather_pattern(const ConeSpec& s, CreasePattern& p, double gather) {
  p.vertices_folded_m = cone_gathered(s, p, gather);
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    PatternEdge& edge = p.edges[e];
    if (edge.face_count() != 2 || edge.fold_angle == 0) continue;
    const int per_ring = 2 * s.pleats + 2;  // wall vertex ring * per_ring + line
    const bool ring = edge.vertices[0] / per_ring == edge.vertices[1] / per_ring;
    const double measured = measured_fold_angle(p, static_cast<int>(e));
    edge.fold_angle = ring || measured * edge.fold_angle < 0 ? 0.0 : measured;
  }
}

// The deployed wall with the gathered state's fold angles (gather_pattern) as its creases'
// targets: `finseg run --fold` gathers it by simulation. Returns the gathered coordinates.
std::vector<Vec3> target_gathered(const ConeSpec& s, CreasePattern& p, double gather) {
  CreasePattern g = p;
  gather_pattern(s, g, gather);
  for (std::size_t e = 0; e < p.edges.size(); ++e) p.edges[e].fold_angle = g.edges[e].fold_angle;
  return g.vertices_folded_m;
}

std::vector<Vec3> face_points(const std::vector<Vec3>& x, const std::vector<int>& face) {
  std::vector<Vec3> out;
  for (int v : face) out.push_back(x[v]);
  return out;
}

// Fixed end plates closing wall ring `ring` (0: the top): a fan of triangles from the ring's
// centre, counter-clockwise seen from outside the cone (from above at the top).
std::string end_plates(const ConeSpec& s, const std::vector<Vec3>& x, int ring, bool top) {
  const int W = 2 * s.pleats + 1, first = cone_wall_vertex(s, ring, 0);
  Vec3 c = Vec3::Zero();
  for (int l = 0; l < W; ++l) c += x[first + l];
  c /= W;
  std::string out;
  auto point = [](const Vec3& v) {
    return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", v.x(), v.y(), v.z());
  };
  for (int l = 0; l < W; ++l) {
    const Vec3 &a = x[first + l], &b = x[first + (l + 1) % W];
    out += fmt::format("      - [{}, {}, {}]\n", point(c), point(top ? a : b), point(top ? b : a));
  }
  return out;
}

// The generated cone scenes' `contact:` section (docs/folding.md, "Contact of the generated
// scenes"): `force` (N; `what` says whose) carried by one face sinks it a quarter of the
// thickness (m), Hertz exponent 1.5; elastic-anchor friction, mu 0.3 / 0.25, its spring
// carrying mu_static times that force at a quarter of the thickness of slip. `keys`: more
// keys for the section's first line.
std::string contact_section(double force, const std::string& what, double thickness,
                            const std::string& keys = "") {
  const double quarter = 0.25 * thickness, mu_static = 0.3;
  return fmt::format(
      "# contact stiffness: {:.3g} N ({}) on one face at a quarter of the thickness;\n"
      "# anchor friction, its spring carrying mu_static x that force at a quarter of the\n"
      "# thickness of slip (docs/folding.md, \"Contact of the generated scenes\")\n"
      "contact: {{stiffness: {:.6g}, exponent: 1.5,{}\n"
      "          friction: {{model: anchor, mu_static: {:g}, mu_dynamic: 0.25,\n"
      "                     tangential_stiffness: {:.6g}}}}}\n",
      force, what, force / std::pow(quarter, 1.5), keys, mu_static, mu_static * force / quarter);
}

// A pull's drive `name` (YAML list item): a gauge of `gauge` N/m at flat point `at` drawn
// `travel` m along `direction` (a YAML list) in 1 s. A `string` pulls along it only, free
// across it and slack when pushed, its tension eased in over a toe of 3 % of its largest pull
// (docs/scene.md, `toe_force`).
std::string pull_drive(const std::string& name, const Vec2& at, const std::string& direction,
                       double gauge, double travel, bool string = false) {
  const std::string string_keys =
      string ? fmt::format("\n     lateral_stiffness: 0, pull_only: true, toe_force: {:.4g},",
                           0.03 * gauge * travel)
             : "";
  return fmt::format(
      "  - {{name: {}, at: {{s: {:.9g}, y: {:.9g}}}, direction: {}, stiffness: {:g},{}\n"
      "     travel: {:.9g}, step: {:.9g}, speed: {:.9g}}}\n",
      name, at.x(), at.y(), direction, gauge, string_keys, travel, travel / 100, travel);
}

// The cone scenes' probes after `probes` (YAML list items): the energy, the contact, and how
// far the wall is from the deployed cone (a shape probe on the pattern's "deployed" frame).
std::string cone_probes(const std::string& probes) {
  return "probes:\n" + probes +
         "  - {name: energy, type: energy}\n"
         "  - {name: contact, type: contact}\n"
         "  - {name: shape, type: shape, shape: deployed}   # RMS distance from the deployed "
         "cone\n"
         "  - {name: unfolding, type: unfolding, shape: deployed}   # which folds open when\n";
}

// The cone scenes' pull after its drives: `probes` (YAML list items), cone_probes, the
// implicit solver to `t_end` s (its error measured at the segments' points when `at_points`),
// the outputs.
std::string pull_run_sections(const std::string& probes, double t_end = 1.0,
                              bool at_points = false) {
  return cone_probes(probes) +
         "# newton_tolerance 0.1 (default 1e-3): on this dissipative pull 20-40 % less CPU,\n"
         "# the force moved less than by halving rtol (docs/solvers.md, \"Newton's tolerance,\n"
         "# measured\")\n" +
         (at_points ? "# error_measure points: a small facet's rotation counts by how far it moves "
                      "its corners;\n# 2 to 6 times fewer Newton iterations on this pull "
                      "(docs/solvers.md, \"The error at a\n# segment's points\")\n"
                    : "") +
         fmt::format(
             "solver: {{type: implicit, t_end: {:.1f}, output_interval: 0.01, dt_max: "
             "0.01,\n         newton_tolerance: 0.1{}}}\n",
             t_end, at_points ? ", error_measure: points" : "") +
         "outputs: {vtk: true, html: true, plot: true}\n";
}

// The cone scenes' pull, drives to outputs: one drive, `top` (pull_drive), and its probe.
std::string top_pull_sections(const Vec2& at, const std::string& direction, double gauge,
                              double travel) {
  return "drives:\n" + pull_drive("top", at, direction, gauge, travel) +
         pull_run_sections("  - {name: top, type: drive, drive: top}\n");
}

// An inflator pulse: from `start` s, `air` times the air that fills the deployed faceted
// frustum to 1 kPa at 300 K, injected over 60 ms (ramps of 10 ms at both ends).
struct InflowPulse {
  double start, air;
};

// The wall as one chamber (YAML `chambers:` section) closed by fixed end plates (triangles
// from each end ring's centre, where the rings start) or, with `caps`, by caps of the end
// rings' own corners that move with the wall; filled from vacuum by the inflator `pulses` and
// bled by a vent to space (docs/gas.md).
std::string chamber_section(const ConeSpec& s, const CreasePattern& p, bool caps,
                            const std::vector<InflowPulse>& pulses) {
  const int G = 2 * s.pleats;
  const double polygon = 0.5 * G * std::sin(2 * kPi / G),
               A_base = polygon * s.base_radius * s.base_radius,
               A_top = polygon * s.top_radius * s.top_radius;
  const double volume = s.height / 3 * (A_base + A_top + std::sqrt(A_base * A_top));
  const double air_kg = 1e3 * volume / (287.05 * 300);
  std::string at, flow, temperature;
  for (const InflowPulse& pulse : pulses) {
    const double t0 = pulse.start, q = pulse.air * air_kg / 0.05;
    at += fmt::format("{}{:g}, {:g}, {:g}, {:g}", at.empty() ? "" : ", ", t0, t0 + 0.01, t0 + 0.05,
                      t0 + 0.06);
    flow += fmt::format("{}0, {:.4g}, {:.4g}, 0", flow.empty() ? "" : ", ", q, q);
    temperature += std::string(temperature.empty() ? "" : ", ") + "300, 300, 300, 300";
  }
  return fmt::format(
      "chambers:\n"
      "  - name: cone\n"
      "    faces:\n"
      "      - {{bodies: all, outward: +z}}\n"
      "{}"
      "    gas: adiabatic\n"
      "    # {:.4g} kg: the deployed volume, {:.4g} m^3, at 1 kPa and 300 K\n"
      "    inflow: {{at: [{}], mass_flow: [{}],\n"
      "             temperature: [{}]}}\n"
      "    vents:\n"
      "      - {{area: 2.0e-6, discharge_coefficient: 0.6}}\n",
      caps ? std::string("    cap_open_ends: true   # the end rings closed by caps\n")
           : "    end_plates:\n" + end_plates(s, p.vertices_folded_m, 0, true) +
                 end_plates(s, p.vertices_folded_m, s.axial_folds + 1, false),
      air_kg, volume, at, flow, temperature);
}

// The wall inflated (chamber_section, one pulse): `start` says where the wall starts;
// `contact_force` (N) sets the contact (contact_section) as for the pull; `damping_time` (s) the
// material's damping (0: none).
void write_inflated_cone(const SheetOptions& o, const ConeSpec& s, const CreasePattern& p,
                         const std::string& start, const std::string& title, int clamped,
                         const std::string& clamped_is, double contact_force, double damping_time,
                         bool caps) {
  const std::string scene_name = fs::path(o.out).filename().string();
  const std::string fold_file = fs::path(o.out).replace_extension(".fold").filename();
  const std::string gas_yaml = fmt::format(
      "# finseg gen cone: base radius {:g} m, top radius {:g} m, height {:g} m, {} pleats, {} "
      "axial folds,\n"
      "# {},\n"
      "{}"
      "{}"
      "# Run: finseg run {} --out inflated\n"
      "title: {}\n{}"
      "fixtures: {{panels: [{}]}}   # {}\n"
      "{}"
      "{}"
      "{}"
      "solver: {{type: implicit, t_end: 0.1, output_interval: 0.001, dt_max: 0.001}}\n"
      "outputs: {{vtk: true, html: true, plot: true}}\n",
      s.base_radius, s.top_radius, s.height, s.pleats, s.axial_folds, start,
      caps ? "# inflated: the wall, its end rings closed by caps of their own corners that move "
             "with\n# it, is one chamber of adiabatic air filled from vacuum by an inflator and "
             "bled by a\n# vent to space (docs/gas.md, \"Caps\").\n"
           : "# inflated: the wall and two fixed end plates (triangles from each end ring's "
             "centre,\n# where the rings start) are one chamber of adiabatic air filled from "
             "vacuum by an\n# inflator and bled by a vent to space (docs/gas.md).\n",
      damping_time > 0 ? "# material.damping_time: without it the facets' ringing holds the "
                         "implicit steps at\n# 1e-8 to 1e-6 s once layers meet (docs/gas.md).\n"
                       : "",
      scene_name, title, sheet_sections(o, fold_file, damping_time), clamped + 1, clamped_is,
      contact_section(contact_force, "the pull's", o.thickness, " initial_overlap: ignore,"),
      chamber_section(s, p, caps, {{0.0, 1.0}}), cone_probes(""));
  write_pair(o, p, gas_yaml);
}

// Mean axial height (z) of the folded centroids of `faces` at coordinates x.
double mean_height(const std::vector<Vec3>& x, const CreasePattern& p,
                   const std::vector<int>& faces) {
  double z = 0;
  for (const int f : faces) z += folded_centroid(x, p.faces[f]).z();
  return z / static_cast<double>(faces.size());
}

// The cone stowed by reflection (`--reflected F`, cone_reflected): the pattern's folded
// coordinates are the stowed wall, radially gathered and axially reflected at once. Its apex
// is pulled along the axis, the base held: every whole facet of the top band drawn up by what
// the two bands' mean heights lack of their distance on the deployed cone, every whole facet
// of the base band held at its centre by a gauge that does not travel (a pin: the facet may
// turn about it, which a clamp would forbid), stiff gauges sharing 10 kN/m an end (one probe
// sums the top's). Inflated, the gauges are strings (free across the axis) drawing each end
// half that rise, and the wall, closed by caps (fixed plates could not follow its ends), is
// filled while they draw its ends apart: the deployment air first, twice as much again as
// the pull ends, and held 0.3 s.
void write_reflected_cone(const SheetOptions& o, const ConeSpec& s, CreasePattern& p,
                          bool inflate) {
  const std::vector<Vec3> deployed = p.vertices_folded_m;
  p.shapes.push_back({"deployed", deployed});  // the shape probe's target
  p.vertices_folded_m = cone_reflected(s, p);
  std::vector<int> top, base;  // the bands' whole facets (wedges 0 and 2 pleats: the seam's halves)
  for (int w = 1; w < 2 * s.pleats; ++w) {
    top.push_back(cone_face(s, 0, w));
    base.push_back(cone_face(s, s.axial_folds, w));
  }
  auto apart = [&](const std::vector<Vec3>& x) {
    return mean_height(x, p, top) - mean_height(x, p, base);
  };
  const double rise = apart(deployed) - apart(p.vertices_folded_m);
  const double top_travel = inflate ? 0.5 * rise : rise, base_travel = rise - top_travel;
  const double gauge = 1e4 / static_cast<double>(top.size());
  // The contact (contact_section): from the largest pull of one gauge, its facet held.
  const double most_force = std::max(gauge * top_travel, 0.1);
  std::string drives = "drives:\n", top_names, base_names;
  for (std::size_t k = 0; k < top.size(); ++k) {
    const std::string t = fmt::format("top{}", k + 1), b = fmt::format("base{}", k + 1);
    drives += pull_drive(t, face_centroid(p, top[k]), "[0, 0, 1]", gauge, top_travel, inflate) +
              pull_drive(b, face_centroid(p, base[k]), "[0, 0, -1]", gauge, base_travel, inflate);
    top_names += (k == 0 ? "" : ", ") + t;
    base_names += (k == 0 ? "" : ", ") + b;
  }
  const std::string scene_name = fs::path(o.out).filename().string();
  const std::string fold_file = fs::path(o.out).replace_extension(".fold").filename();
  // Pinned, the base band's drives stay put: their probe would have no pull to plot against.
  std::string probes = fmt::format("  - {{name: top, type: drive, drives: [{}]}}\n", top_names);
  if (inflate) probes += fmt::format("  - {{name: base, type: drive, drives: [{}]}}\n", base_names);
  const std::string how =
      inflate ? fmt::format(
                    "# Its ends are drawn apart along the axis, nothing clamped, by strings (free "
                    "across the\n# axis, slack when pushed) on the top band's whole facets up "
                    "and the base band's down,\n# {:.4g} m each (probes top and base sum each "
                    "end's), while gas fills the wall closed by caps\n# of its end rings: the "
                    "deployment air, then twice as much again from 0.9 s, held to 1.3 s\n# "
                    "(docs/gas.md, \"The cone stowed by reflection, inflated\").\n",
                    top_travel)
              : fmt::format(
                    "# Its apex is pulled along the axis, the base held: the top band's whole "
                    "facets drawn up\n# {:.4g} m (probe top sums their gauges), the base band's "
                    "pinned at their centres by gauges\n# that do not travel (free to turn: "
                    "clamped, the base locks the pull); the base band stays\n# gathered "
                    "(docs/folding.md, \"The apex pulled, the base held\").\n",
                    top_travel);
  const std::string yaml = fmt::format(
      "# finseg gen cone: base radius {:g} m, top radius {:g} m, height {:g} m, {} pleats, {} "
      "axial folds,\n"
      "# open ends, stowed by reflection: the wall gathered {:g} of the way to every other "
      "generator on the axis\n"
      "# and each band below a ring reflected across the ring's plane (radially and axially "
      "folded at once,\n"
      "# every facet rigid, no layers touching; docs/folding.md, \"The cone stowed by "
      "reflection\").\n"
      "# No rigid motion leads out of it: the pull strains the facets.\n{}"
      "# Triangle cells (--cells triangles) bend where quadrilaterals lock.\n"
      "#   finseg run {} --out deploy\n"
      "title: cone stowed by reflection, {}\n{}"
      "# material.damping_time 1 ms: the implicit solver passes the bands' snaps\n"
      "{}{}{}{}",
      s.base_radius, s.top_radius, s.height, s.pleats, s.axial_folds, s.reflect_gather, how,
      scene_name,
      inflate ? "inflated while its ends are drawn apart" : "its apex pulled along the axis",
      sheet_sections(o, fold_file, 1e-3),
      contact_section(most_force, "a gauge's largest pull", o.thickness,
                      " initial_overlap: ignore,"),
      drives, inflate ? chamber_section(s, p, true, {{0.0, 1.0}, {0.9, 2.0}}) : "",
      pull_run_sections(probes, inflate ? 1.3 : 1.0, !inflate));
  write_pair(o, p, yaml);
}

// "disc" or "open" for --top / --base.
bool disc_end(const std::string& value, const char* option) {
  if (value != "disc" && value != "open") {
    throw InputError("<cli>", option, fmt::format("'{}'; allowed: disc, open", value));
  }
  return value == "disc";
}

void register_cone(CLI::App* gen) {
  auto o = std::make_shared<SheetOptions>();
  auto s = std::make_shared<ConeSpec>();
  auto angles = std::make_shared<std::pair<double, double>>(120.0, 150.0);
  auto fraction = std::make_shared<double>(0.9);
  auto ends = std::make_shared<std::pair<std::string, std::string>>("open", "open");
  auto fold_steps = std::make_shared<int>(0);
  auto stowed = std::make_shared<double>(-1);
  auto gathered = std::make_shared<double>(-1);
  CLI::App* c = gen->add_subcommand(
      "cone",
      "conical skin with radial pleats and axial zigzag folds; by default gathered by folding "
      "(--fold-to-gathered 0.9), a base facet pulled back out");
  c->add_option("--base-radius", s->base_radius, "m")->capture_default_str();
  c->add_option("--top-radius", s->top_radius, "m")->capture_default_str();
  c->add_option("--height", s->height, "m")->capture_default_str();
  c->add_option("--pleats", s->pleats, "radial pleats (2 x pleats generators, M/V alternating)")
      ->capture_default_str();
  c->add_option("--axial-folds", s->axial_folds, "ring creases between top and base")
      ->capture_default_str();
  c->add_option("--pleat-fold-angle", angles->first, "stowed fold of the generators, deg (0, 180)")
      ->capture_default_str();
  c->add_option("--axial-fold-angle", angles->second, "stowed fold of the rings, deg (0, 180)")
      ->capture_default_str();
  auto fan = std::make_shared<bool>(false);
  c->add_flag("--fan-fold", *fan,
              "fold the deployed cone by driving every crease towards its stowed angle (the "
              "implicit solver unless --fold-steps), the top pulled along the axis; the only "
              "start with --top/--base disc, --wrap or --fold-fraction (docs/folding.md)");
  CLI::Option* fraction_option =
      c->add_option("--fold-fraction", *fraction,
                    "with --fan-fold: share of the stowed angles folded to, (0, 1]")
          ->capture_default_str();
  c->add_option("--top", ends->first,
                "top end: open, or (with --fan-fold) disc: hub + pleated band, pulled")
      ->capture_default_str();
  c->add_option("--base", ends->second,
                "base end: open, or (with --fan-fold) disc: its hub clamped")
      ->capture_default_str();
  c->add_option("--fold-steps", *fold_steps,
                "folding by the static solver in this many load steps (0: implicit, dynamic)")
      ->capture_default_str();
  CLI::Option* stowed_option =
      c->add_option("--stowed", *stowed,
                    "start from the fan stack Z-folded by this ring angle, deg [0, 180] (open "
                    "ends only); the base band pulled away from the top band");
  auto inflate = std::make_shared<bool>(false);
  c->add_flag(
      "--inflate", *inflate,
      "with --gathered: deploy by gas instead of the pull (one chamber of the wall closed by "
      "fixed end plates, or by caps with --caps, an inflator and a vent to space; docs/gas.md); "
      "with --reflected: by gas in the wall closed by caps while strings draw its ends apart");
  auto caps = std::make_shared<bool>(false);
  c->add_flag("--caps", *caps,
              "with --inflate: close the chamber by caps of the end rings' own corners, moving "
              "with the wall, instead of fixed end plates (docs/gas.md, Caps; --reflected "
              "always has caps)");
  CLI::Option* gathered_option = c->add_option(
      "--gathered", *gathered,
      "start from the wall gathered along its symmetric rigid motion, share [0, 1) of the way "
      "that brings every other generator onto the axis (open ends only; no facets coincide, "
      "contact on); a base facet pulled back out");
  auto fold_gather = std::make_shared<double>(0.9);
  CLI::Option* fold_gather_option = c->add_option(
      "--fold-to-gathered", *fold_gather,
      "start from the deployed cone and let `finseg run --fold` gather it by simulation, share "
      "[0, 1) as for --gathered (open ends only; static solver, --fold-steps or 20 load steps); "
      "deploy from its checkpoint with --state: a base facet pulled back out as for --gathered. "
      "The start when no other is chosen, with share 0.9");
  c->add_flag("--wrap", s->wrap,
              "generator 0 a mountain too: pleats + 1 mountains among the generators, the "
              "assignment a flat stack with thickness needs (docs/folding.md); with --fan-fold "
              "only");
  CLI::Option* reflected_option = c->add_option(
      "--reflected", s->reflect_gather,
      "start stowed by reflection: the wall gathered this share [0, 1) of the way (as for "
      "--gathered), each band below a ring reflected across the ring's plane, rings zigzagged "
      "to make that exact (open ends only; radially and axially folded, no layers touching); "
      "its apex pulled along the axis, the base band pinned (with --inflate: both ends drawn "
      "apart by strings while gas fills it); with --cells triangles the facets bend where "
      "quadrilateral segments lock (docs/fold.md, Triangle cells)");
  add_sheet_options(c, *o);
  c->callback([o, s, angles, fraction, fraction_option, ends, fold_steps, stowed, stowed_option,
               gathered, gathered_option, inflate, caps, fold_gather, fold_gather_option,
               reflected_option, fan] {
    check_sheet(*o);
    if (!(*fraction > 0 && *fraction <= 1)) {
      throw InputError("<cli>", "--fold-fraction", fmt::format("{}; allowed (0, 1]", *fraction));
    }
    if (*fold_steps < 0 || *fold_steps > 100000) {
      throw InputError("<cli>", "--fold-steps", fmt::format("{}; allowed 0..100000", *fold_steps));
    }
    if (*caps && !*inflate) throw InputError("<cli>", "--caps", "needs --inflate");
    s->top_disc = disc_end(ends->first, "--top");
    s->base_disc = disc_end(ends->second, "--base");
    s->pleat_fold_angle = angles->first * kDegToRad;
    s->axial_fold_angle = angles->second * kDegToRad;
    if (*fan) {
      for (const CLI::Option* other :
           {stowed_option, gathered_option, fold_gather_option, reflected_option}) {
        if (other->count() > 0) {
          throw InputError("<cli>", "--fan-fold", "not with " + other->get_name());
        }
      }
    }
    if (reflected_option->count() > 0) {
      for (const CLI::Option* other : {stowed_option, gathered_option, fold_gather_option}) {
        if (other->count() > 0) {
          throw InputError("<cli>", "--reflected", "not with " + other->get_name());
        }
      }
      if (!(s->reflect_gather >= 0 && s->reflect_gather < 1)) {
        throw InputError("<cli>", "--reflected",
                         fmt::format("{}; allowed [0, 1)", s->reflect_gather));
      }
      if (s->top_disc || s->base_disc) {
        throw InputError("<cli>", "--reflected", "needs --top open --base open");
      }
      if (s->wrap) throw InputError("<cli>", "--wrap", "not with --reflected");
      CreasePattern p;
      in_scene_file(
          "<cli>", [&] { p = cone_crease_pattern(*s); }, kCliNames);
      write_reflected_cone(*o, *s, p, *inflate);
      return;
    }
    const bool from_stack = stowed_option->count() > 0;
    if (from_stack && (s->top_disc || s->base_disc)) {
      throw InputError("<cli>", "--stowed", "needs --top open --base open");
    }
    if (from_stack && !(*stowed >= 0 && *stowed <= 180)) {
      throw InputError("<cli>", "--stowed", fmt::format("{} deg; allowed [0, 180]", *stowed));
    }
    const bool from_gathered = gathered_option->count() > 0;
    if (from_gathered && (s->top_disc || s->base_disc)) {
      throw InputError("<cli>", "--gathered", "needs --top open --base open");
    }
    if (from_gathered && from_stack) {
      throw InputError("<cli>", "--gathered", "give --gathered or --stowed, not both");
    }
    if (from_gathered && !(*gathered >= 0 && *gathered < 1)) {
      throw InputError("<cli>", "--gathered", fmt::format("{}; allowed [0, 1)", *gathered));
    }
    if (*inflate && !from_gathered) {
      throw InputError("<cli>", "--inflate", "needs --gathered or --reflected");
    }
    const bool to_gathered_given = fold_gather_option->count() > 0;
    if (to_gathered_given && (from_gathered || from_stack)) {
      throw InputError("<cli>", "--fold-to-gathered", "not with --gathered or --stowed");
    }
    if (to_gathered_given && (s->top_disc || s->base_disc)) {
      throw InputError("<cli>", "--fold-to-gathered", "needs --top open --base open");
    }
    if (!*fan && (s->top_disc || s->base_disc)) {
      throw InputError("<cli>", s->top_disc ? "--top" : "--base",
                       "disc needs --fan-fold (only the fan fold drives a cone with end discs)");
    }
    // Folding to the gathered wall is the start when none is chosen: the fan fold of a closed
    // cone is locked, and the open one's stops short of the stack (docs/folding.md).
    const bool to_gathered = !*fan && !from_stack && !from_gathered;
    if (to_gathered && !(*fold_gather >= 0 && *fold_gather < 1)) {
      throw InputError("<cli>", "--fold-to-gathered",
                       fmt::format("{}; allowed [0, 1)", *fold_gather));
    }
    if (!*fan && fraction_option->count() > 0) {
      throw InputError("<cli>", "--fold-fraction",
                       "needs --fan-fold (--fold-to-gathered's share says how far the wall "
                       "gathers)");
    }
    if (s->wrap && !*fan) {
      throw InputError("<cli>", "--wrap",
                       "needs --fan-fold (the fan stack and the gathered wall are the fan "
                       "assignment's)");
    }
    CreasePattern p;
    in_scene_file(
        "<cli>", [&] { p = cone_crease_pattern(*s); }, kCliNames);
    const std::vector<Vec3> deployed = p.vertices_folded_m;
    p.shapes.push_back({"deployed", deployed});  // the shape probe's target
    if (from_stack) p.vertices_folded_m = cone_fan_stack(*s, p, *stowed * kDegToRad);
    if (from_gathered) gather_pattern(*s, p, *gathered);
    const std::vector<Vec3> gathered_x =
        to_gathered ? target_gathered(*s, p, *fold_gather) : std::vector<Vec3>{};
    // Clamped: the base hub, else the base band's wedge 1 (the first whole facet). Pulled:
    // the top hub, else the top band's facet across the axis from that (wedge pleats + 1).
    // From the fan stack: the top band's wedge 1 clamped, the base band's pulled away from
    // the apex along the stack's middle (+x).
    // Gathered: the top band's wedge 1 clamped, the base band's facet across the axis from it
    // pulled radially out to where it sits on the deployed cone.
    // Folded to gathered: as gathered, from where the folding run leaves the wall.
    const bool gathers = from_gathered || to_gathered;
    const int clamped = from_stack || gathers ? cone_face(*s, 0, 1)
                        : s->base_disc        ? cone_hub_face(*s, false)
                                              : cone_face(*s, s->axial_folds, 1);
    const int pulled = from_stack    ? cone_face(*s, s->axial_folds, 1)
                       : gathers     ? cone_face(*s, s->axial_folds, s->pleats + 1)
                       : s->top_disc ? cone_hub_face(*s, true)
                                     : cone_face(*s, 0, s->pleats + 1);
    std::string direction = from_stack ? "[1, 0, 0]" : "[0, 0, 1]";
    double travel = 0.8 * s->height;
    if (gathers) {
      // Radially out in the gathered wall's frame; folded to gathered, that frame is where
      // the folding run leaves the wall (moved rigidly so that the clamped face, held during
      // the folding, is where it is deployed): the same pull as --gathered's.
      const std::vector<Vec3>& at = from_gathered ? p.vertices_folded_m : gathered_x;
      const Vec3 now = folded_centroid(at, p.faces[pulled]),
                 there = folded_centroid(deployed, p.faces[pulled]);
      const Vec2 out(now.x(), now.y());
      Vec3 radial(out.x() / out.norm(), out.y() / out.norm(), 0);
      if (to_gathered) {
        radial = best_rigid_fit(face_points(gathered_x, p.faces[clamped]),
                                face_points(deployed, p.faces[clamped]))
                     .R *
                 radial;
      }
      direction = fmt::format("[{:.9g}, {:.9g}, {:.9g}]", radial.x(), radial.y(), radial.z());
      travel = Vec2(there.x(), there.y()).norm() - out.norm();
    }
    const Vec2 top = face_centroid(p, pulled);
    // Contact from the thickness and the load (contact_section): the gauge's largest pull
    // (stiffness x travel), carried by one face, sinks it a quarter of the thickness.
    const double gauge = 20, most_force = std::max(gauge * travel, 0.1);
    const std::string scene_name = fs::path(o->out).filename().string();
    const std::string fold_file = fs::path(o->out).replace_extension(".fold").filename();
    // Gathering is a rigid motion: the static solver lands on it (docs/folding.md).
    const int load_steps = *fold_steps > 0 ? *fold_steps : to_gathered ? 20 : 0;
    const std::string folding_solver =
        load_steps > 0
            ? fmt::format("{{type: static, load_steps: {}, max_iterations: 50}}", load_steps)
            : std::string("{type: implicit, t_end: 1.2, output_interval: 0.02, dt_max: 0.01}");
    // Finer than 2 x 2 a face, the gathering (a rigid motion of the faces) is folded on 2 x 2
    // and carried over: at 7 x 7 (8 575 segments) 27 s of CPU against a fold that crept
    // (docs/folding.md, "Folding on a coarser segmentation"; 1 x 1 strays on the lab cone).
    const std::string coarse_fold =
        to_gathered && o->segment_size == 0 && o->subdivisions > 2
            ? "  coarse_subdivisions: 2   # folded on 2 x 2 segments a face, then carried over\n"
            : "";
    const std::string how_to_run =
        from_gathered
            ? fmt::format(
                  "# Starts gathered ({:g} of the way to every other generator on the axis): "
                  "no facets coincide;\n"
                  "# contact ignores the overlap of facets that start closer than the thickness "
                  "(docs/contact.md).\n"
                  "# Pull it open (contact on): finseg run {} --out deploy\n",
                  *gathered, scene_name)
        : to_gathered
            ? fmt::format(
                  "# Fold it: the static solver gathers the wall ({:g} of the way to every other "
                  "generator on the axis):\n"
                  "#   finseg run {} --fold --out folded\n"
                  "# Deploy it by pulling a base facet back out (contact on):\n"
                  "#   finseg run {} --state folded/checkpoint.json --out deploy\n",
                  *fold_gather, scene_name, scene_name)
        : from_stack
            ? fmt::format(
                  "# Starts stowed: the fan stack Z-folded to {:g} deg, its layers coinciding;\n"
                  "# contact ignores their overlap at the start (docs/contact.md).\n"
                  "# Pull it open: finseg run {} --out deploy\n",
                  *stowed, scene_name)
            : fmt::format(
                  "# Fold it (contact on): finseg run {0} --fold --out folded\n"
                  "# Deploy it by pulling the top: finseg run {0} --state "
                  "folded/checkpoint.json --out deploy\n",
                  scene_name);
    const std::string yaml = fmt::format(
        "# finseg gen cone: base radius {:g} m, top radius {:g} m, height {:g} m, {} pleats, {} "
        "axial folds,\n"
        "# top {}, base {}{}.\n"
        "{}"
        "title: {}\n{}"
        "fixtures: {{panels: [{}]}}   # {}\n"
        "{}"
        "folding:\n"
        "  fraction: {:g}\n"
        "  duration: 1.0\n"
        "{}"
        "  solver: {}\n"
        "{}",
        s->base_radius, s->top_radius, s->height, s->pleats, s->axial_folds, ends->first,
        ends->second,
        s->wrap ? ",\n# generator 0 a mountain too (--wrap: pleats + 1 mountains, docs/folding.md)"
                : "",
        how_to_run,
        from_gathered ? "gathered cone, a base facet pulled back out"
        : to_gathered ? "cone gathered by folding, a base facet pulled back out"
                      : "folded cone pulled open by its top",
        sheet_sections(*o, fold_file), clamped + 1,
        from_stack || gathers ? "one face of the top band"
        : s->base_disc        ? "the base disc's hub"
                              : "one face of the base band",
        contact_section(most_force, "gauge stiffness x travel", o->thickness,
                        from_stack || gathers ? " initial_overlap: ignore," : ""),
        to_gathered ? 1.0 : *fraction, coarse_fold, folding_solver,
        top_pull_sections(top, direction, gauge, travel));
    if (!*inflate) {
      write_pair(*o, p, yaml);
      return;
    }
    write_inflated_cone(*o, *s, p,
                        fmt::format("gathered {:g} of the way to every other generator on the axis "
                                    "(no facets coincide)",
                                    *gathered),
                        "gathered cone inflated", clamped, "one face of the top band", most_force,
                        0.0, *caps);
  });
}

}  // namespace

void register_pattern_generators(CLI::App* gen) {
  register_miura(gen);
  register_cone(gen);
}

}  // namespace finseg::cli
