// finseg pattern check|info FILE [--unit U]: validates a FOLD crease pattern (docs/fold.md)
// and prints its counts; finseg pattern zigzag ... [--out FILE]: writes the zigzag strip's
// crease pattern as FOLD (stdout or FILE, atomically).
#include <fmt/format.h>

#include <cmath>
#include <map>
#include <memory>
#include <optional>

#include "apps/finseg/commands.hpp"
#include "core/error.hpp"
#include "core/text.hpp"
#include "patterns/flat_tube_pattern.hpp"
#include "patterns/fold_format.hpp"
#include "patterns/miura_tube_pattern.hpp"
#include "patterns/tube_pattern.hpp"
#include "patterns/zigzag_pattern.hpp"

namespace finseg::cli {

namespace {

struct ReadOptions {
  std::string file, unit;
};

std::optional<double> unit_scale(const std::string& unit) {
  if (unit.empty()) return std::nullopt;
  if (const auto m = metres_per_fold_unit(unit)) return m;
  const double v = parse_number(unit, "<cli>", "--unit");
  require_positive(v, "<cli>", "--unit", "m per unit");
  return v;
}

void print_counts(const std::string& file, const CreasePattern& p) {
  std::map<char, int> count;
  for (const PatternEdge& e : p.edges) ++count[static_cast<char>(e.assignment)];
  std::string kinds;
  for (const auto& [letter, n] : count)
    kinds += fmt::format("{}{} {}", kinds.empty() ? "" : ", ", n, letter);
  fmt::print("{}: valid: {} vertices, {} faces, {} edges ({}){}\n", file, p.vertices_flat_m.size(),
             p.faces.size(), p.edges.size(), kinds,
             p.vertices_folded_m.empty() ? "" : ", folded coordinates");
}

void print_info(const CreasePattern& p) {
  Eigen::AlignedBox2d box;
  for (const Vec2& v : p.vertices_flat_m) box.extend(v);
  std::size_t min_sides = SIZE_MAX, max_sides = 0;
  for (const auto& f : p.faces) {
    min_sides = std::min(min_sides, f.size());
    max_sides = std::max(max_sides, f.size());
  }
  fmt::print("  FOLD {} by '{}', title '{}'\n", p.meta.file_spec, p.meta.file_creator,
             p.meta.frame_title);
  fmt::print("  flat extent {:.6g} x {:.6g} m, faces of {}..{} sides\n", box.sizes().x(),
             box.sizes().y(), min_sides, max_sides);
  if (!p.has_fold_angles) return fmt::print("  no fold angles\n");
  double lo = 0, hi = 0;
  for (const PatternEdge& e : p.edges) {
    lo = std::min(lo, e.fold_angle);
    hi = std::max(hi, e.fold_angle);
  }
  fmt::print("  fold angles {:.6g} .. {:.6g} deg (valley positive)\n", lo / kDegToRad,
             hi / kDegToRad);
}

void register_read(CLI::App* pattern, const char* name, const char* what, bool info) {
  auto o = std::make_shared<ReadOptions>();
  CLI::App* c = pattern->add_subcommand(name, what);
  c->add_option("file", o->file, "FOLD file")->required();
  c->add_option("--unit", o->unit,
                "length of one unit of a unitless file: m, cm, mm, um, nm, in, pt or metres");
  c->callback([o, info] {
    const CreasePattern p = read_fold(o->file, unit_scale(o->unit));
    print_counts(o->file, p);
    if (info) print_info(p);
  });
}

void register_zigzag_pattern(CLI::App* pattern) {
  auto spec = std::make_shared<ZigzagSpec>();
  auto deg = std::make_shared<double>(80);
  auto out = std::make_shared<std::string>();
  CLI::App* c = pattern->add_subcommand("zigzag", "the zigzag strip's crease pattern as FOLD");
  c->add_option("--length", spec->length, "whole strip, m");
  c->add_option("--width", spec->width, "m");
  c->add_option("--panels", spec->panels, "number of panels");
  c->add_option("--fold-angle", *deg, "angle panel/horizontal, deg");
  c->add_option("--pattern", spec->pattern, "P/V per crease, e.g. PVPVP (default: alternate)");
  c->add_option("--out", *out, "write the FOLD file to FILE instead of standard output");
  c->callback([spec, deg, out] {
    spec->fold_angle = *deg * kDegToRad;
    spec->fixed_panels = {1};  // the pull test is not part of the pattern: any valid values
    spec->pulled_crease = 1;
    validate(*spec, "<cli>");
    const CreasePattern p = zigzag_crease_pattern(*spec);
    if (out->empty()) return fmt::print("{}", fold_text(p));
    write_fold(*out, p);
    fmt::print(stderr, "wrote {}\n", *out);
  });
}

// --flat: the lay-flat tube (flat_tube_crease_pattern); --facets is then per layer.
CreasePattern flat_tube_from_options(int facets, int rows, double length, double gap, double width,
                                     double seal_length) {
  if (facets < 2 || facets > 256) {
    throw InputError("<cli>", "--facets", fmt::format("{}; with --flat 2..256 per layer", facets));
  }
  if (rows < 3 || rows > 10000) {
    throw InputError("<cli>", "--rows", fmt::format("{}; with --flat 3..10000", rows));
  }
  require_positive(length, "<cli>", "--length", "m");
  require_positive(width, "<cli>", "--width", "m");
  if (!(gap > 0 && gap < width / facets)) {
    throw InputError(
        "<cli>", "--flat",
        fmt::format("{} m; allowed (0, --width / --facets = {} m)", gap, width / facets));
  }
  if (!(seal_length > 0 && 2 * seal_length < length)) {
    throw InputError(
        "<cli>", "--seal-length",
        fmt::format("{} m; allowed (0, --length / 2 = {} m)", seal_length, length / 2));
  }
  FlatTubeSpec s;
  s.layer_facets = facets;
  s.rows = rows;
  s.width = width;
  s.gap = gap;
  s.length = length;
  s.seal_length = seal_length;
  return flat_tube_crease_pattern(s);
}

void register_tube(CLI::App* pattern) {
  struct Options {
    int facets = 12, rows = 8;
    double radius = 0.025, length = 0.4, fold_angle_deg = 0;
    double gap = 0, width = 0.04, seal_length = 2e-3;
    bool caps = false;
    std::string out;
  };
  auto o = std::make_shared<Options>();
  CLI::App* c = pattern->add_subcommand(
      "tube", "a tube rolled from a rectangle (seamed), optionally with Z-fold creases, as FOLD");
  c->add_option("--facets", o->facets,
                "flat facets around the circumference (>= 3); with --flat: per layer (>= 2)");
  c->add_option("--rows", o->rows,
                "rows along the length (>= 1; >= 2 with --fold-angle; >= 3 with --flat, the "
                "first and last the seals)");
  CLI::Option* radius = c->add_option("--radius", o->radius, "corner radius, m");
  c->add_option("--length", o->length, "m");
  CLI::Option* fold =
      c->add_option("--fold-angle", o->fold_angle_deg,
                    "Z-fold: largest fold angle of the inner row lines, deg in [-180, 180] (0: a "
                    "straight tube, rows joined)");
  CLI::Option* caps =
      c->add_flag("--caps", o->caps,
                  "close both ends by N-gon caps glued on by seams (always with --fold-angle; the "
                  "rows then meet at flat creases where the fold angle is 0)");
  CLI::Option* flat = c->add_option(
      "--flat", o->gap,
      "GAP, m: the lay-flat tube instead, stowed flattened (two layers of --facets facets "
      "GAP apart, joined by side gussets GAP high) and closed at both ends by flat seals "
      "(docs/fold.md, The lay-flat tube); (0, --width / --facets)");
  CLI::Option* width =
      c->add_option("--width", o->width, "with --flat: each layer's flattened width, m")
          ->capture_default_str();
  CLI::Option* seal = c->add_option("--seal-length", o->seal_length,
                                    "with --flat: axial length of each seal row, m, "
                                    "(0, --length / 2)")
                          ->capture_default_str();
  c->add_option("--out", o->out, "write the FOLD file to FILE instead of standard output");
  c->callback([o, radius, fold, caps, flat, width, seal] {
    CreasePattern p;
    if (flat->count() > 0) {
      for (const CLI::Option* other : {radius, fold, caps}) {
        if (other->count() > 0) {
          throw InputError("<cli>", other->get_name(),
                           "not with --flat (--width, --facets per "
                           "layer)");
        }
      }
      p = flat_tube_from_options(o->facets, o->rows, o->length, o->gap, o->width, o->seal_length);
    } else {
      for (const CLI::Option* only_flat : {width, seal}) {
        if (only_flat->count() > 0) {
          throw InputError("<cli>", only_flat->get_name(), "only with --flat");
        }
      }
      const bool zigzag = o->fold_angle_deg != 0;
      if (o->facets < 3) throw InputError("<cli>", "--facets", fmt::format("{}; >= 3", o->facets));
      if (o->rows < (zigzag ? 2 : 1)) {
        throw InputError("<cli>", "--rows",
                         fmt::format("{}; >= {}", o->rows, zigzag ? "2 with --fold-angle" : "1"));
      }
      require_positive(o->radius, "<cli>", "--radius", "m");
      require_positive(o->length, "<cli>", "--length", "m");
      if (!(std::abs(o->fold_angle_deg) <= 180)) {
        throw InputError("<cli>", "--fold-angle",
                         fmt::format("{}; deg in [-180, 180]", o->fold_angle_deg));
      }
      p = !zigzag && !o->caps
              ? tube_crease_pattern(o->facets, o->rows, o->radius, o->length)
              : zfolded_tube_crease_pattern(o->facets, o->rows, o->radius, o->length,
                                            o->fold_angle_deg * kDegToRad);
    }
    if (o->out.empty()) return fmt::print("{}", fold_text(p));
    write_fold(o->out, p);
    fmt::print(stderr, "wrote {}\n", o->out);
  });
}

// The Miura tube (miura_tube_crease_pattern): two mirrored two-row Miura strips seamed along
// their ridges, stowed along its length at --fold-angle.
void register_miura_tube(CLI::App* pattern) {
  struct Options {
    MiuraTubeSpec spec;
    double sector_deg = 60, fold_deg = 80;
    bool open = false;
    std::string out;
  };
  auto o = std::make_shared<Options>();
  CLI::App* c = pattern->add_subcommand(
      "miura-tube",
      "a closed tube of two mirrored Miura strips seamed along their ridges, stowed Z-folded "
      "along its length (docs/fold.md, The Miura tube), as FOLD");
  c->add_option("--columns", o->spec.columns, "panel columns along the tube, 1..1000")
      ->capture_default_str();
  c->add_option("--side-a", o->spec.side_a, "the rhombic section's side, m (> 0)")
      ->capture_default_str();
  c->add_option("--side-b", o->spec.side_b, "the panels' side along the tube, m (> 0)")
      ->capture_default_str();
  c->add_option("--sector-angle", o->sector_deg, "the parallelograms' acute angle, deg in (0, 90)")
      ->capture_default_str();
  c->add_option("--fold-angle", o->fold_deg,
                "stowed: the panels' angle to the tube's mid-plane (Schenk and Guest's theta), "
                "deg in (0, 90); 45 is the largest volume, towards 90 the accordion")
      ->capture_default_str();
  c->add_flag("--open", o->open, "leave both ends open (no rhombic caps)");
  c->add_option("--out", o->out, "write the FOLD file to FILE instead of standard output");
  c->callback([o] {
    MiuraTubeSpec s = o->spec;
    if (s.columns < 1 || s.columns > 1000) {
      throw InputError("<cli>", "--columns", fmt::format("{}; allowed 1..1000", s.columns));
    }
    require_positive(s.side_a, "<cli>", "--side-a", "m");
    require_positive(s.side_b, "<cli>", "--side-b", "m");
    if (!(o->sector_deg > 0 && o->sector_deg < 90)) {
      throw InputError("<cli>", "--sector-angle",
                       fmt::format("{} deg; allowed (0, 90)", o->sector_deg));
    }
    if (!(o->fold_deg > 0 && o->fold_deg < 90)) {
      throw InputError("<cli>", "--fold-angle",
                       fmt::format("{} deg; allowed (0, 90): flat and fully folded enclose no "
                                   "volume",
                                   o->fold_deg));
    }
    s.sector_angle = o->sector_deg * kDegToRad;
    s.fold_angle = o->fold_deg * kDegToRad;
    s.caps = !o->open;
    const CreasePattern p = miura_tube_crease_pattern(s);
    fmt::print(stderr,
               "volume {:.6g} m^3 stowed, largest {:.6g} m^3 (at 45 deg), length {:.6g} m\n",
               miura_tube_volume(s, s.fold_angle), miura_tube_max_volume(s),
               miura_tube_shape(s, s.fold_angle).length);
    if (o->out.empty()) return fmt::print("{}", fold_text(p));
    write_fold(o->out, p);
    fmt::print(stderr, "wrote {}\n", o->out);
  });
}

}  // namespace

void register_pattern(CLI::App& app) {
  CLI::App* pattern = app.add_subcommand("pattern", "read, check and write FOLD crease patterns");
  pattern->require_subcommand(1);
  register_read(pattern, "check", "validate a FOLD file and print its counts", false);
  register_read(pattern, "info", "check, then print extent, face sizes and fold angles", true);
  register_zigzag_pattern(pattern);
  register_tube(pattern);
  register_miura_tube(pattern);
}

}  // namespace finseg::cli
