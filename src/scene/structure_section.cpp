// Material, sheet, discretisation, stiffness, fixtures (panels), gravity, contact, the
// zigzag generator's section and the crease pattern section of a scene file (docs/scene.md).
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>

#include "core/so3.hpp"
#include "generators/pattern_sheet.hpp"
#include "generators/sheet.hpp"
#include "generators/zigzag.hpp"
#include "patterns/fold_format.hpp"
#include "patterns/segment_mesh.hpp"
#include "scene/scene_parts.hpp"

namespace finseg {
namespace {

// Physical ranges, wide enough for any sheet (gels to diamond, aerogel to osmium, graphene
// to plate) and narrow enough that the stiffness and mass matrices stay well scaled.
const Range kModulusRange = interval(1e2, 1e13, false, false, "Pa");
const Range kDensityRange = interval(1e-2, 1e5, false, false, "kg/m^3");
const Range kThicknessRange = interval(1e-10, 1, false, false, "m");
const Range kSizeRange = interval(1e-6, 1e4, false, false, "m");

void read_material(const Fields& root, SheetSpec& s) {
  if (!root.has("material")) root.fail("material", "required section (youngs_modulus, density)");
  const Fields m(root.node("material"), root.context("material"),
                 {"youngs_modulus", "poisson_ratio", "density", "damping_time"});
  s.youngs_modulus = m.number("youngs_modulus", kModulusRange);
  s.poisson_ratio = m.number("poisson_ratio", 0.3, interval(0, 0.5, false, true));
  s.density = m.number("density", kDensityRange);
  s.damping_time = m.number("damping_time", 0.0, non_negative("s"));
}

void read_sheet_size(const Fields& sheet, SheetSpec& s) {
  s.length = sheet.number("length", kSizeRange);
  s.width = sheet.number("width", kSizeRange);
  s.thickness = sheet.number("thickness", kThicknessRange);
}

void read_discretisation(const Fields& root, SheetSpec& s, bool zigzag) {
  const Fields d(root.node("discretisation"), root.context("discretisation"),
                 {"segments", "segments_across", "crease_refinement", "cell_weights"});
  s.cells_along = d.integer("segments", zigzag ? 8 : 16, 1, 1000000);
  s.cells_across = d.integer("segments_across", 1, 1, 100000);
  s.crease_refinement = d.number("crease_refinement", zigzag ? 2.0 : 1.0, positive(""));
  s.cell_weights = d.numbers("cell_weights", positive(""));
}

void read_stiffness(const Fields& root, StiffnessOverride& o) {
  const Fields k(root.node("stiffness"), root.context("stiffness"),
                 {"bending_rigidity", "twist_rigidity", "inplane_rigidity", "axial_rigidity",
                  "shear_rigidity"});
  o.bending_rigidity = k.optional_number("bending_rigidity", positive("N m^2"));
  o.twist_rigidity = k.optional_number("twist_rigidity", positive("N m^2"));
  o.inplane_rigidity = k.optional_number("inplane_rigidity", positive("N m^2"));
  o.axial_rigidity = k.optional_number("axial_rigidity", positive("N"));
  o.shear_rigidity = k.optional_number("shear_rigidity", positive("N"));
}

Fields fixtures_of(const Fields& root) {
  return Fields(root.node("fixtures"), root.context("fixtures"),
                {"clamp_start", "panels", "bodies"});
}

std::vector<FoldSpec> read_folds(const Fields& sheet) {
  std::vector<FoldSpec> folds;
  const auto items =
      sequence(sheet.node("folds"), sheet.context("folds"), "folds {s, angle_deg, law}");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Fields f(items[i], {sheet.context().file, item_field(sheet.field("folds"), i)},
                   {"s", "angle_deg", "law"});
    FoldSpec fold;
    fold.s = f.number("s", positive("m"));
    fold.angle = f.number("angle_deg", interval(-180, 180, false, false, "deg")) * kDegToRad;
    if (!f.has("law")) f.fail("law", "required: a crease law map (docs/crease-data.md)");
    fold.law = read_crease_law(f.node("law"), f.context("law"));
    folds.push_back(fold);
  }
  return folds;
}

std::string sheet_field(const std::string& api) {
  static const std::map<std::string, std::string> names{
      {"fixtures.fixed_panels", "fixtures.panels"}, {"damping_time", "material.damping_time"}};
  if (auto it = names.find(api); it != names.end()) return it->second;
  if (api.rfind("folds[", 0) == 0) {
    std::string f = "sheet." + api;
    if (f.size() > 6 && f.substr(f.size() - 6) == ".angle") f += "_deg";
    return f;
  }
  return api;
}

// Model of a general sheet: SheetSpec from the sections, then gravity and contact.
Model read_general_sheet(const Fields& root, const Fields& sheet, SheetSpec s) {
  read_sheet_size(sheet, s);
  s.origin_W = sheet.vector3("origin", Vec3::Zero(), "m");
  s.R_W0 = so3_exp<double>(Vec3(
      0, sheet.number("pitch_deg", 0.0, interval(-180, 180, false, false, "deg")) * kDegToRad, 0));
  s.folds = read_folds(sheet);
  const Fields fix = fixtures_of(root);
  s.clamp_start = fix.flag("clamp_start", false);
  for (int p : fix.integers("panels", 1, 1000000)) s.fixed_panels.push_back(p - 1);
  check_model_memory(static_cast<double>(s.cells_along) * static_cast<double>(s.folds.size() + 1),
                     s.cells_across, root.context().file,
                     "discretisation.segments x segments_across");
  Model m;
  in_scene_file(
      root.context().file, [&] { m = build_sheet_model(s); }, sheet_field);
  m.gravity_W = root.vector3("gravity", Vec3::Zero(), "m/s^2");
  if (root.has("contact"))
    m.contact = read_contact_section(root.node("contact"), root.context("contact"), panel_count(m));
  return m;
}

std::string zigzag_field(const std::string& api) {
  static const std::map<std::string, std::string> names{
      {"length", "sheet.length"},
      {"width", "sheet.width"},
      {"thickness", "sheet.thickness"},
      {"fold_angle", "zigzag.fold_angle_deg"},
      {"fixed_panels", "fixtures.panels"},
      {"fixtures.fixed_panels", "fixtures.panels"},
      {"damping_time", "material.damping_time"}};
  if (auto it = names.find(api); it != names.end()) return it->second;
  for (const char* key : {"panels", "pattern", "pulled_crease", "pull_direction", "pull_step",
                          "pull_travel", "gauge_stiffness", "crease_laws"}) {
    if (api == key) return std::string("zigzag.") + key;
  }
  return sheet_field(api);
}

std::vector<std::shared_ptr<const CreaseLaw>> read_zigzag_laws(const Fields& z) {
  std::vector<std::shared_ptr<const CreaseLaw>> laws;
  if (z.has("crease_law") && z.has("crease_laws")) {
    z.fail("crease_laws", "give either crease_law (one for all) or crease_laws (one per crease)");
  }
  if (z.has("crease_law"))
    laws.push_back(read_crease_law(z.node("crease_law"), z.context("crease_law")));
  const auto items = sequence(z.node("crease_laws"), z.context("crease_laws"), "crease laws");
  for (std::size_t i = 0; i < items.size(); ++i) {
    laws.push_back(
        read_crease_law(items[i], {z.context().file, item_field(z.field("crease_laws"), i)}));
  }
  return laws;
}

// Model of the paper's zigzag strip (generators/zigzag.hpp) from the `zigzag:` section.
Model read_zigzag(const Fields& root, const Fields& sheet, const SheetSpec& base) {
  for (const char* key : {"origin", "pitch_deg", "folds"}) {
    if (sheet.has(key))
      sheet.fail(key, "not available with a zigzag: section (the generator places the folds)");
  }
  const Fields z(
      root.node("zigzag"), root.context("zigzag"),
      {"panels", "fold_angle_deg", "pattern", "crease_law", "crease_laws", "pulled_crease",
       "pull_direction", "pull_step", "pull_travel", "pull_speed", "gauge_stiffness"});
  ZigzagSpec s;
  SheetSpec size;
  read_sheet_size(sheet, size);
  s.length = size.length;
  s.width = size.width;
  s.thickness = size.thickness;
  s.youngs_modulus = base.youngs_modulus;
  s.poisson_ratio = base.poisson_ratio;
  s.density = base.density;
  s.damping_time = base.damping_time;
  s.segments_per_panel = base.cells_along;
  s.segments_across = base.cells_across;
  s.crease_refinement = base.crease_refinement;
  s.overrides = base.overrides;
  if (!base.cell_weights.empty()) {
    root.fail("discretisation.cell_weights", "not available with a zigzag: section");
  }
  s.panels = z.integer("panels", s.panels, 2, 100000);
  if (z.has("fold_angle_deg")) {
    s.fold_angle = z.number("fold_angle_deg", interval(0, 90, true, true, "deg")) * kDegToRad;
  }
  s.pattern = z.word("pattern", "");
  s.crease_laws = read_zigzag_laws(z);
  s.pulled_crease = z.integer("pulled_crease", s.pulled_crease, 1, 100000);
  const Vec3 dir = z.vector3("pull_direction", s.pull_direction_W, "unit vector");
  if (!(dir.norm() > 0)) z.fail("pull_direction", "must be a non-zero vector");
  s.pull_direction_W = dir / dir.norm();
  s.pull_step = z.number("pull_step", s.pull_step, positive("m"));
  s.pull_travel = z.number("pull_travel", s.pull_travel, non_negative("m (0: default)"));
  s.gauge_stiffness = z.number("gauge_stiffness", s.gauge_stiffness, positive("N/m"));
  const Fields fix = fixtures_of(root);
  if (fix.has("clamp_start"))
    fix.fail("clamp_start", "not available with a zigzag: use fixtures.panels");
  s.fixed_panels =
      fix.has("panels") ? fix.integers("panels", 1, 1000000) : std::vector<int>{1, s.panels};
  s.gravity = false;  // set below from the scene's gravity vector
  bool replace_contact = false;
  if (root.has("contact")) {
    const YAML::Node c = root.node("contact");
    const bool only_switch = c.IsMap() && c.size() == 1 && c["enabled"];
    if (only_switch) {
      s.contact = Fields(c, root.context("contact"), {"enabled"}).flag("enabled", true);
    } else {
      replace_contact = true;
    }
  }
  check_model_memory(static_cast<double>(s.segments_per_panel) * s.panels, s.segments_across,
                     root.context().file,
                     "discretisation.segments x segments_across x zigzag.panels");
  Model m;
  in_scene_file(
      root.context().file,
      [&] {
        validate(s, "<api>");
        m = build_zigzag_model(s);
      },
      zigzag_field);
  if (const auto v = z.optional_number("pull_speed", non_negative("m/s"))) m.drives[0].speed = *v;
  m.gravity_W = root.vector3("gravity", Vec3(0, 0, -9.81), "m/s^2");
  if (replace_contact) {
    m.contact = read_contact_section(root.node("contact"), root.context("contact"), panel_count(m));
    if (m.contact.groups.empty()) m.contact.groups = adjacent_panel_groups(s.panels);
  }
  return m;
}

// Length of one unit of a unitless FOLD file: a unit name (mm, ...) or metres per unit.
std::optional<double> read_fold_unit(const Fields& p) {
  if (!p.has("unit")) return std::nullopt;
  const YAML::Node u = p.node("unit");
  if (u.IsScalar()) {
    if (const auto named = metres_per_fold_unit(u.Scalar()); named && u.Scalar() != "unit") {
      return named;
    }
  }
  return p.number("unit", positive("m per unit, or m, cm, mm, um, nm, in, pt"));
}

// pattern.crease_laws: [{edges: [indices into the FOLD file's edge arrays, 0-based], law:
// crease law map}, ...].
std::vector<EdgeCreaseLaw> read_edge_laws(const Fields& p) {
  std::vector<EdgeCreaseLaw> out;
  const std::vector<YAML::Node> items =
      sequence(p.node("crease_laws"), p.context("crease_laws"), "a list of {edges, law}");
  for (std::size_t k = 0; k < items.size(); ++k) {
    const Fields item(items[k], {p.context().file, item_field(p.field("crease_laws"), k)},
                      {"edges", "law"});
    EdgeCreaseLaw l;
    l.edges = item.integers("edges", 0, 100000000);
    if (l.edges.empty()) item.fail("edges", "missing or empty: list FOLD edge indices (0-based)");
    if (!item.has("law")) item.fail("law", "missing");
    l.law = read_crease_law(item.node("law"), item.context("law"));
    out.push_back(std::move(l));
  }
  return out;
}

// pattern.soft_seams: [{seams: [indices into the FOLD file's finseg:seams, 0-based], scale:
// (0, 1]}, ...].
std::vector<SoftSeams> read_soft_seams(const Fields& p) {
  std::vector<SoftSeams> out;
  const std::vector<YAML::Node> items =
      sequence(p.node("soft_seams"), p.context("soft_seams"), "a list of {seams, scale}");
  for (std::size_t k = 0; k < items.size(); ++k) {
    const Fields item(items[k], {p.context().file, item_field(p.field("soft_seams"), k)},
                      {"seams", "scale"});
    SoftSeams q;
    q.seams = item.integers("seams", 0, 100000000);
    if (q.seams.empty()) {
      item.fail("seams", "missing or empty: list finseg:seams indices (0-based)");
    }
    if (!item.has("scale")) item.fail("scale", "missing");
    q.scale = item.number("scale", interval(0, 1, true, false));
    out.push_back(std::move(q));
  }
  return out;
}

// Model of a sheet cut from a FOLD crease pattern (generators/pattern_sheet.hpp).
Model read_pattern_sheet(const Fields& root, const Fields& sheet, const SheetSpec& base,
                         std::string& pattern_file) {
  for (const char* key : {"length", "width", "folds", "pitch_deg"}) {
    if (sheet.has(key)) sheet.fail(key, "not available with a pattern: the pattern gives it");
  }
  if (root.has("discretisation")) {
    root.fail("discretisation", "not available with a pattern: use pattern.subdivisions");
  }
  if (root.has("stiffness")) root.fail("stiffness", "not available with a pattern");
  const Fields p(root.node("pattern"), root.context("pattern"),
                 {"file", "unit", "subdivisions", "segment_size", "crease_refinement", "cells",
                  "start", "crease_law_length", "crease_rest", "mountain_law", "valley_law",
                  "crease_laws", "soft_seams"});
  std::filesystem::path path = p.required_word("file");
  if (path.is_relative()) path = std::filesystem::path(root.context().file).parent_path() / path;
  pattern_file = path.string();
  const CreasePattern pattern = read_fold(pattern_file, read_fold_unit(p));
  PatternSheetSpec s;
  s.thickness = sheet.number("thickness", kThicknessRange);
  s.youngs_modulus = base.youngs_modulus;
  s.poisson_ratio = base.poisson_ratio;
  s.density = base.density;
  s.damping_time = base.damping_time;
  s.subdivisions = p.integer("subdivisions", 2, 1, 64);
  if (p.has("segment_size")) {
    if (p.has("subdivisions")) p.fail("segment_size", "give either subdivisions or segment_size");
    s.segment_size = p.number("segment_size", positive("m"));
  }
  s.crease_refinement = p.number("crease_refinement", 1.0, interval(1, 100, false, false));
  const std::string cells = p.word("cells", "quadrilaterals");
  if (cells != "quadrilaterals" && cells != "triangles")
    p.fail("cells", "'" + cells + "'; allowed: quadrilaterals, triangles");
  s.triangle_cells = cells == "triangles";
  const std::string start = p.word("start", "folded");
  if (start != "folded" && start != "flat")
    p.fail("start", "'" + start + "'; allowed: folded, flat");
  s.start_folded = start == "folded";
  s.crease_law_length = p.number("crease_law_length", 1.0, positive("m"));
  const std::string rest = p.word("crease_rest", "law");
  if (rest != "law" && rest != "pattern")
    p.fail("crease_rest", "'" + rest + "'; allowed: law, pattern");
  s.laws_rest_at_pattern = rest == "pattern";
  if (p.has("mountain_law")) {
    s.mountain_law = read_crease_law(p.node("mountain_law"), p.context("mountain_law"));
  }
  if (p.has("valley_law")) {
    s.valley_law = read_crease_law(p.node("valley_law"), p.context("valley_law"));
  }
  s.edge_laws = read_edge_laws(p);
  s.soft_seams = read_soft_seams(p);
  s.origin_W = sheet.vector3("origin", Vec3::Zero(), "m");
  const Fields fix = fixtures_of(root);
  if (fix.has("clamp_start")) fix.fail("clamp_start", "not available with a pattern: use panels");
  for (int f : fix.integers("panels", 1, 1000000)) s.fixed_faces.push_back(f - 1);
  {
    const std::vector<int> counts =
        edge_cell_counts(pattern, subdivision_of(s), root.context().file, p.field("segment_size"));
    const double across = std::max(1, *std::max_element(counts.begin(), counts.end()));
    check_model_memory(planned_cell_count(pattern, counts, s.triangle_cells) / across, across,
                       root.context().file,
                       s.segment_size > 0 ? p.field("segment_size") : p.field("subdivisions"));
  }
  Model m;
  in_scene_file(
      root.context().file, [&] { m = build_pattern_model(pattern, s); },
      [&](const std::string& api) {
        if (api.rfind("edges_assignment", 0) == 0) {
          return "pattern.mountain_law / valley_law (" + pattern_file + " " + api + ")";
        }
        if (api == "fixtures.fixed_faces") return std::string("fixtures.panels");
        if (api == "discretisation.subdivisions") return std::string("pattern.subdivisions");
        if (api == "discretisation.segment_size") return std::string("pattern.segment_size");
        if (api == "discretisation.crease_refinement") {
          return std::string("pattern.crease_refinement");
        }
        if (api.rfind("crease_laws", 0) == 0) return "pattern." + api;
        if (api.rfind("soft_seams", 0) == 0) return "pattern." + api;
        if (api == "creases.law_length") return std::string("pattern.crease_law_length");
        return api;
      });
  m.gravity_W = root.vector3("gravity", Vec3::Zero(), "m/s^2");
  if (root.has("contact"))
    m.contact = read_contact_section(root.node("contact"), root.context("contact"), panel_count(m));
  return m;
}

}  // namespace

void in_scene_file(const std::string& file, const std::function<void()>& build,
                   const std::function<std::string(const std::string&)>& scene_field) {
  try {
    build();
  } catch (const InputError& e) {
    if (e.file() != "<api>") throw;
    const std::string prefix = e.file() + ": " + e.field() + ": ";
    std::string what = e.what();
    if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
    throw InputError(file, scene_field ? scene_field(e.field()) : e.field(), what);
  }
}

Model read_structure(const Fields& root, bool& zigzag, std::string& pattern_file) {
  zigzag = root.has("zigzag");
  if (zigzag && root.has("pattern")) root.fail("pattern", "give either zigzag: or pattern:");
  SheetSpec base;
  read_material(root, base);
  if (!root.has("sheet")) root.fail("sheet", "required section (length, width, thickness)");
  const Fields sheet(root.node("sheet"), root.context("sheet"),
                     {"length", "width", "thickness", "origin", "pitch_deg", "folds"});
  Model m;
  if (root.has("pattern")) {
    m = read_pattern_sheet(root, sheet, base, pattern_file);
  } else {
    read_discretisation(root, base, zigzag);
    read_stiffness(root, base.overrides);
    m = zigzag ? read_zigzag(root, sheet, base) : read_general_sheet(root, sheet, base);
  }
  m.source = root.context().file;
  return m;
}

}  // namespace finseg
