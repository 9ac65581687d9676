// Crease laws in scene files (docs/crease-data.md):
//   {type: linear, stiffness: <N m/rad>, rest_angle_deg: <deg>}
//   {type: measured, file: creases.csv, pressing_time: <s>, ends: natural|not-a-knot,
//    openings_before: <n>, lever: <m>}
// both with optional opened_above_deg / closed_below_deg (opening count) and
//   relaxation: {coefficient_deg: <deg>, time_constant_s: <s>, age_s: <s>,
//                reference_age_s: <s>}
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "core/error.hpp"
#include "core/text.hpp"
#include "elements/crease_law.hpp"
#include "elements/crease_laws/crease_data.hpp"
#include "elements/crease_laws/measured.hpp"
#include "scene/sections.hpp"

namespace finseg {

namespace {

void check_keys(const YAML::Node& node, const YamlContext& ctx, const std::set<std::string>& ok) {
  for (const auto& kv : node) {
    const std::string key = kv.first.as<std::string>();
    if (!ok.count(key)) {
      std::string list;
      for (const std::string& k : ok) list += (list.empty() ? "" : ", ") + k;
      throw InputError(ctx.file, ctx.field + "." + key, "unknown key; allowed: " + list);
    }
  }
}

double number(const YAML::Node& node, const YamlContext& ctx, const std::string& key,
              const std::string& range) {
  const YAML::Node v = node[key];
  double x = 0;
  try {
    x = v.as<double>();
  } catch (const YAML::Exception&) {
    throw InputError(ctx.file, ctx.field + "." + key, "must be a number " + range);
  }
  if (!std::isfinite(x)) {
    throw InputError(ctx.file, ctx.field + "." + key, "must be finite " + range);
  }
  refuse_subnormal(x, ctx.file, ctx.field + "." + key);
  return x;
}

std::optional<double> optional_number(const YAML::Node& node, const YamlContext& ctx,
                                      const std::string& key, const std::string& range) {
  if (!node[key]) return std::nullopt;
  return number(node, ctx, key, range);
}

std::string text(const YAML::Node& node, const YamlContext& ctx, const std::string& key) {
  try {
    return node[key].as<std::string>();
  } catch (const YAML::Exception&) {
    throw InputError(ctx.file, ctx.field + "." + key, "must be a string");
  }
}

OpeningRule read_rule(const YAML::Node& node, const YamlContext& ctx) {
  OpeningRule rule;
  if (auto v = optional_number(node, ctx, "opened_above_deg", "(deg, 0..360)")) {
    rule.opened_above = *v * kDegToRad;
  }
  if (auto v = optional_number(node, ctx, "closed_below_deg", "(deg, 0..360)")) {
    rule.closed_below = *v * kDegToRad;
  }
  validate_opening_rule(rule, ctx.file, ctx.field);
  return rule;
}

std::shared_ptr<const CreaseLaw> with_relaxation(std::shared_ptr<const CreaseLaw> law,
                                                 const YAML::Node& node, const YamlContext& ctx) {
  if (!node["relaxation"]) return law;
  const YAML::Node r = node["relaxation"];
  const YamlContext rc{ctx.file, ctx.field + ".relaxation"};
  if (!r.IsMap()) {
    throw InputError(rc.file, rc.field,
                     "must be a map {coefficient_deg, time_constant_s, age_s, reference_age_s}");
  }
  check_keys(r, rc, {"coefficient_deg", "time_constant_s", "age_s", "reference_age_s"});
  for (const char* key : {"coefficient_deg", "time_constant_s"}) {
    if (!r[key]) throw InputError(rc.file, rc.field + "." + key, "required");
  }
  const double c = number(r, rc, "coefficient_deg", "(deg per e-fold of time)") * kDegToRad;
  const double tau = number(r, rc, "time_constant_s", "(s, > 0)");
  const double age = optional_number(r, rc, "age_s", "(s, >= 0)").value_or(0.0);
  const double ref = optional_number(r, rc, "reference_age_s", "(s, >= 0)").value_or(age);
  return std::make_shared<RelaxingCreaseLaw>(std::move(law), c, tau, age, ref, rc.file, rc.field);
}

}  // namespace

std::shared_ptr<const CreaseLaw> read_crease_law(const YAML::Node& node, const YamlContext& ctx) {
  if (!node || !node.IsMap() || !node["type"]) {
    throw InputError(ctx.file, ctx.field,
                     "must be a map with type: linear | measured (docs/crease-data.md)");
  }
  const std::string type = text(node, ctx, "type");
  if (type == "linear") {
    check_keys(node, ctx,
               {"type", "stiffness", "rest_angle_deg", "opened_above_deg", "closed_below_deg",
                "relaxation"});
    for (const char* key : {"stiffness", "rest_angle_deg"}) {
      if (!node[key]) throw InputError(ctx.file, ctx.field + "." + key, "required");
    }
    const double k = number(node, ctx, "stiffness", "(N m/rad, >= 0)");
    if (k < 0) {
      throw InputError(ctx.file, ctx.field + ".stiffness",
                       fmt::format("{} must be >= 0 N m/rad", k));
    }
    const double rest = number(node, ctx, "rest_angle_deg", "(deg)") * kDegToRad;
    std::shared_ptr<const CreaseLaw> law =
        std::make_shared<LinearCreaseLaw>(k, rest, read_rule(node, ctx));
    return with_relaxation(std::move(law), node, ctx);
  }
  if (type == "measured") {
    check_keys(node, ctx,
               {"type", "file", "pressing_time", "ends", "openings_before", "lever",
                "opened_above_deg", "closed_below_deg", "relaxation"});
    if (!node["file"]) throw InputError(ctx.file, ctx.field + ".file", "required");
    std::filesystem::path path = text(node, ctx, "file");
    if (path.is_relative()) path = std::filesystem::path(ctx.file).parent_path() / path;
    const std::optional<double> lever = optional_number(node, ctx, "lever", "(m, > 0)");
    if (lever && !(*lever > 0)) {
      throw InputError(ctx.file, ctx.field + ".lever", fmt::format("{} must be > 0 m", *lever));
    }
    const CreaseData data = read_crease_data(path.string(), lever);
    MeasuredLawOptions o;
    o.pressing_time = optional_number(node, ctx, "pressing_time", "(s, within the measured)");
    if (node["ends"]) {
      const std::string ends = text(node, ctx, "ends");
      if (!parse_spline_ends(ends, o.ends)) {
        throw InputError(ctx.file, ctx.field + ".ends",
                         quoted(ends) + "; allowed: natural, not-a-knot");
      }
    }
    if (node["openings_before"]) {
      const double n = number(node, ctx, "openings_before", "(integer >= 0)");
      if (n < 0 || n != std::floor(n) || n > 1e6) {
        throw InputError(ctx.file, ctx.field + ".openings_before",
                         fmt::format("{} must be an integer >= 0", n));
      }
      o.openings_before = static_cast<int>(n);
    }
    o.rule = read_rule(node, ctx);
    std::shared_ptr<const CreaseLaw> law =
        std::make_shared<MeasuredCreaseLaw>(data, o, ctx.file, ctx.field);
    return with_relaxation(std::move(law), node, ctx);
  }
  throw InputError(ctx.file, ctx.field + ".type", quoted(type) + "; allowed: linear, measured");
}

}  // namespace finseg
