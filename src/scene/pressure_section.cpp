// The `pressures:` section of a scene file (docs/scene.md): pressure loads on segment faces.
#include <fmt/format.h>

#include <algorithm>

#include "scene/scene_parts.hpp"

namespace finseg {

std::vector<int> selected_bodies(const Fields& f, const Model& m) {
  if (f.has("panels") == f.has("bodies")) f.fail("panels", "give either panels: [..] or bodies");
  std::vector<int> out;
  if (f.has("panels")) {
    const std::vector<int> panels = f.integers("panels", 1, panel_count(m));
    if (panels.empty()) f.fail("panels", "must list at least one panel (1-based)");
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
      if (std::count(panels.begin(), panels.end(), m.bodies[i].panel + 1)) {
        out.push_back(static_cast<int>(i));
      }
    }
    return out;
  }
  const YAML::Node node = f.node("bodies");
  if (node.IsScalar()) {
    if (node.Scalar() != "all")
      f.fail("bodies", "'" + node.Scalar() + "'; allowed: all, or a list of body names");
    for (std::size_t i = 0; i < m.bodies.size(); ++i) out.push_back(static_cast<int>(i));
    return out;
  }
  const std::vector<std::string> names = f.words("bodies");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const int b = m.body_index(names[i]);
    if (b < 0) {
      throw InputError(
          f.context().file, item_field(f.field("bodies"), i),
          fmt::format("'{}' is not a body of the model (finseg inspect lists them)", names[i]));
    }
    out.push_back(b);
  }
  if (out.empty()) f.fail("bodies", "must name at least one body, or be 'all'");
  return out;
}

bool plus_z_side(const Fields& f, const std::string& key, const std::string& meaning) {
  const std::string side = f.required_word(key);
  if (side == "+z") return true;
  if (side == "-z") return false;
  f.fail(key, "'" + side + "'; allowed: +z, -z (" + meaning + ")");
}

void read_pressure_table(const Fields& f, PressureDef& d) {
  const Fields t(f.node("table"), f.context("table"), {"versus", "at", "pressure"});
  const std::string versus = t.required_word("versus");
  if (versus == "time") {
    d.versus = PressureVersus::Time;
  } else if (versus == "load_scale") {
    d.versus = PressureVersus::LoadScale;
  } else {
    t.fail("versus", "'" + versus + "'; allowed: time, load_scale");
  }
  if (!t.has("at") || !t.has("pressure")) t.fail("at", "required: at: [..] and pressure: [..]");
  d.at = t.numbers("at", any_finite(versus == "time" ? "s" : ""));
  d.pressures = t.numbers("pressure", non_negative("Pa"));
  if (d.at.empty()) t.fail("at", "the table needs at least one row");
}

void read_pressures(const Fields& root, Model& m) {
  const auto items = sequence(root.node("pressures"), root.context("pressures"), "pressures");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Fields f(items[i], {root.context().file, item_field("pressures", i)},
                   {"name", "panels", "bodies", "side", "pressure", "table"});
    PressureDef d;
    d.name = f.word("name", fmt::format("pressure{}", i + 1));
    d.bodies = selected_bodies(f, m);
    d.side = plus_z_side(f, "side", "the face of the body frame pressed") ? PressureSide::PlusZ
                                                                          : PressureSide::MinusZ;
    if (f.has("pressure") == f.has("table")) {
      f.fail("pressure", "give either pressure: P (Pa) or table: {versus, at, pressure}");
    }
    if (f.has("pressure")) {
      d.pressure = f.number("pressure", non_negative("Pa"));
    } else {
      read_pressure_table(f, d);
    }
    m.pressures.push_back(d);
  }
}

}  // namespace finseg
