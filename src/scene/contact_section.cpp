// The `contact:` section of a scene file (docs/contact.md, "Scene file").
#include <fmt/format.h>

#include <set>
#include <string>

#include "collision/contact_laws.hpp"
#include "core/error.hpp"
#include "scene/sections.hpp"

namespace finseg {

namespace {

std::string join(const std::string& a, const std::string& b) {
  return a.empty() ? b : a + "." + b;
}

void check_keys(const YAML::Node& node, const YamlContext& ctx,
                const std::set<std::string>& known) {
  for (const auto& kv : node) {
    const std::string key = kv.first.as<std::string>();
    if (!known.count(key)) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw InputError(ctx.file, join(ctx.field, key), "unknown key; allowed: " + list);
    }
  }
}

double read_number(const YAML::Node& node, const YamlContext& ctx, const std::string& key,
                   double fallback) {
  const YAML::Node v = node[key];
  if (!v) return fallback;
  try {
    return v.as<double>();
  } catch (const YAML::Exception&) {
    throw InputError(ctx.file, join(ctx.field, key), "must be a number");
  }
}

std::string read_word(const YAML::Node& node, const YamlContext& ctx, const std::string& key,
                      const std::string& fallback) {
  const YAML::Node v = node[key];
  if (!v) return fallback;
  if (!v.IsScalar()) throw InputError(ctx.file, join(ctx.field, key), "must be a word");
  return v.as<std::string>();
}

}  // namespace

ContactDef read_contact_section(const YAML::Node& node, const YamlContext& ctx) {
  ContactDef c;
  if (!node || node.IsNull()) return c;
  if (!node.IsMap())
    throw InputError(ctx.file, ctx.field, "must be a map of contact parameters (docs/contact.md)");
  check_keys(
      node, ctx,
      {"enabled", "stiffness", "exponent", "damping_law", "damping", "damping_depth", "restitution",
       "min_impact_speed", "friction", "panel_exclusion", "groups", "margin"});
  c.enabled = true;
  if (node["enabled"]) {
    try {
      c.enabled = node["enabled"].as<bool>();
    } catch (const YAML::Exception&) {
      throw InputError(ctx.file, join(ctx.field, "enabled"), "must be true or false");
    }
  }
  c.stiffness = read_number(node, ctx, "stiffness", c.stiffness);
  c.exponent = read_number(node, ctx, "exponent", c.exponent);
  c.damping = read_number(node, ctx, "damping", c.damping);
  c.damping_depth = read_number(node, ctx, "damping_depth", c.damping_depth);
  c.restitution = read_number(node, ctx, "restitution", c.restitution);
  c.min_impact_speed = read_number(node, ctx, "min_impact_speed", c.min_impact_speed);
  c.margin = read_number(node, ctx, "margin", c.margin);
  const std::string law = read_word(node, ctx, "damping_law", "impact");
  if (law == "impact") {
    c.damping_law = ContactDamping::Impact;
  } else if (law == "hunt_crossley") {
    c.damping_law = ContactDamping::HuntCrossley;
  } else if (law == "lankarani_nikravesh") {
    c.damping_law = ContactDamping::LankaraniNikravesh;
  } else if (law == "flores") {
    c.damping_law = ContactDamping::Flores;
  } else {
    throw InputError(ctx.file, join(ctx.field, "damping_law"),
                     "'" + law + "'; allowed: impact, hunt_crossley, lankarani_nikravesh, flores");
  }
  if (node["damping_law"] && c.damping_law != ContactDamping::Impact && !node["restitution"])
    throw InputError(ctx.file, join(ctx.field, "restitution"),
                     "required by damping_law " + law + " (a value in (0, 1])");
  if (const YAML::Node p = node["panel_exclusion"]) {
    try {
      c.panel_exclusion = p.as<int>();
    } catch (const YAML::Exception&) {
      throw InputError(ctx.file, join(ctx.field, "panel_exclusion"), "must be an integer >= 0");
    }
  }
  if (const YAML::Node g = node["groups"]) {
    const std::string f = join(ctx.field, "groups");
    if (!g.IsSequence())
      throw InputError(ctx.file, f, "must be a list of panel lists, e.g. [[0, 1], [2, 3]]");
    for (std::size_t i = 0; i < g.size(); ++i) {
      if (!g[i].IsSequence())
        throw InputError(ctx.file, fmt::format("{}[{}]", f, i), "must be a list of panel indices");
      std::vector<int> panels;
      for (std::size_t j = 0; j < g[i].size(); ++j) {
        try {
          panels.push_back(g[i][j].as<int>());
        } catch (const YAML::Exception&) {
          throw InputError(ctx.file, fmt::format("{}[{}][{}]", f, i, j),
                           "must be a panel index >= 0");
        }
      }
      c.groups.push_back(panels);
    }
  }
  if (const YAML::Node fr = node["friction"]) {
    const YamlContext fctx{ctx.file, join(ctx.field, "friction")};
    if (!fr.IsMap())
      throw InputError(ctx.file, fctx.field, "must be a map with model: none|continuous|anchor");
    check_keys(fr, fctx,
               {"model", "mu_static", "mu_dynamic", "stiction_speed", "friction_speed",
                "tangential_stiffness", "tangential_damping"});
    const std::string model = read_word(fr, fctx, "model", "continuous");
    if (model == "none") {
      c.friction = FrictionModel::None;
    } else if (model == "continuous") {
      c.friction = FrictionModel::Continuous;
    } else if (model == "anchor") {
      c.friction = FrictionModel::Anchor;
    } else {
      throw InputError(ctx.file, join(fctx.field, "model"),
                       "'" + model + "'; allowed: none, continuous, anchor");
    }
    c.mu_static = read_number(fr, fctx, "mu_static", c.mu_static);
    c.mu_dynamic = read_number(fr, fctx, "mu_dynamic", c.mu_dynamic);
    c.stiction_speed = read_number(fr, fctx, "stiction_speed", c.stiction_speed);
    c.friction_speed = read_number(fr, fctx, "friction_speed", c.friction_speed);
    c.tangential_stiffness = read_number(fr, fctx, "tangential_stiffness", c.tangential_stiffness);
    c.tangential_damping = read_number(fr, fctx, "tangential_damping", c.tangential_damping);
  }
  validate_contact(c, ctx.file);
  return c;
}

}  // namespace finseg
