// The `contact:` section of a scene file (docs/contact.md, "Scene file").
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "collision/contact_laws.hpp"
#include "core/error.hpp"
#include "core/text.hpp"
#include "scene/sections.hpp"
#include "scene/yaml_fields.hpp"

namespace finseg {

ContactDef read_contact_section(const YAML::Node& node, const YamlContext& ctx, int panels) {
  ContactDef c;
  if (!node || node.IsNull()) return c;
  if (!node.IsMap())
    throw InputError(ctx.file, ctx.field, "must be a map of contact parameters (docs/contact.md)");
  const Fields f(node, ctx,
                 {"enabled", "stiffness", "exponent", "damping_law", "damping", "damping_depth",
                  "restitution", "min_impact_speed", "friction", "panel_exclusion", "groups",
                  "crease_zone", "margin", "samples_per_edge", "initial_overlap"});
  // Numbers are only parsed here; validate_contact() checks their ranges (also for models
  // built through the API).
  auto number = [](const Fields& fs, const char* key, double fallback, const char* unit) {
    return fs.number(key, fallback, any_finite(unit));
  };
  c.enabled = f.flag("enabled", true);
  c.stiffness = number(f, "stiffness", c.stiffness, "N/m^e");
  c.exponent = number(f, "exponent", c.exponent, "");
  c.damping = number(f, "damping", c.damping, "N s/m");
  c.damping_depth = number(f, "damping_depth", c.damping_depth, "m");
  c.restitution = number(f, "restitution", c.restitution, "");
  c.min_impact_speed = number(f, "min_impact_speed", c.min_impact_speed, "m/s");
  c.margin = number(f, "margin", c.margin, "m");
  if (f.has("crease_zone")) c.crease_zone = number(f, "crease_zone", 0, "m");
  const std::string law = f.word("damping_law", "impact");
  if (law == "impact") {
    c.damping_law = ContactDamping::Impact;
  } else if (law == "hunt_crossley") {
    c.damping_law = ContactDamping::HuntCrossley;
  } else if (law == "lankarani_nikravesh") {
    c.damping_law = ContactDamping::LankaraniNikravesh;
  } else if (law == "flores") {
    c.damping_law = ContactDamping::Flores;
  } else {
    f.fail("damping_law",
           quoted(law) + "; allowed: impact, hunt_crossley, lankarani_nikravesh, flores");
  }
  if (f.has("damping_law") && c.damping_law != ContactDamping::Impact && !f.has("restitution"))
    f.fail("restitution", "required by damping_law " + law + " (a value in (0, 1])");
  c.panel_exclusion = f.integer("panel_exclusion", c.panel_exclusion, 0, 1000000);
  c.samples_per_edge = f.integer("samples_per_edge", c.samples_per_edge, 2, 16);
  const std::string overlap = f.word("initial_overlap", "push");
  if (overlap == "push") {
    c.initial_overlap = InitialOverlap::Push;
  } else if (overlap == "ignore") {
    c.initial_overlap = InitialOverlap::Ignore;
  } else {
    f.fail("initial_overlap", quoted(overlap) + "; allowed: push, ignore");
  }
  const std::vector<YAML::Node> groups =
      sequence(f.node("groups"), f.context("groups"), "panel lists");
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const YamlContext gctx{ctx.file, item_field(f.field("groups"), i)};
    std::vector<int> group;
    const std::vector<YAML::Node> items = sequence(groups[i], gctx, "panel indices");
    for (std::size_t j = 0; j < items.size(); ++j) {
      const YamlContext pctx{ctx.file, item_field(gctx.field, j)};
      const double last = panels > 0 ? panels : 1e6;
      const double p =
          read_number_at(items[j], pctx, interval(1, last, false, false, "(panel, from 1)"));
      if (p != std::floor(p)) throw InputError(ctx.file, pctx.field, "must be a whole number");
      group.push_back(static_cast<int>(p) - 1);
    }
    c.groups.push_back(group);
  }
  if (f.has("friction")) {
    const Fields fr(f.node("friction"), f.context("friction"),
                    {"model", "mu_static", "mu_dynamic", "stiction_speed", "friction_speed",
                     "tangential_stiffness", "tangential_damping"});
    const std::string model = fr.word("model", "continuous");
    if (model == "none") {
      c.friction = FrictionModel::None;
    } else if (model == "continuous") {
      c.friction = FrictionModel::Continuous;
    } else if (model == "anchor") {
      c.friction = FrictionModel::Anchor;
    } else {
      fr.fail("model", quoted(model) + "; allowed: none, continuous, anchor");
    }
    c.mu_static = number(fr, "mu_static", c.mu_static, "");
    c.mu_dynamic = number(fr, "mu_dynamic", c.mu_dynamic, "");
    c.stiction_speed = number(fr, "stiction_speed", c.stiction_speed, "m/s");
    c.friction_speed = number(fr, "friction_speed", c.friction_speed, "m/s");
    c.tangential_stiffness = number(fr, "tangential_stiffness", c.tangential_stiffness, "N/m");
    c.tangential_damping = number(fr, "tangential_damping", c.tangential_damping, "N s/m");
  }
  validate_contact(c, ctx.file);
  return c;
}

}  // namespace finseg
