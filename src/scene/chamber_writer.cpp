// The `chambers:` section written back from a model (docs/scene.md), so that a scene with
// chambers round-trips through read_scene().
#include <fmt/format.h>

#include "scene/scene_writer.hpp"

namespace finseg {
namespace {

std::string numbers(const std::vector<double>& x) {
  std::string out = "[";
  for (std::size_t i = 0; i < x.size(); ++i) out += (i ? ", " : "") + yaml_number(x[i]);
  return out + "]";
}

// Consecutive faces with the same outward side share one entry.
std::string faces(const Model& m, const ChamberDef& c) {
  std::string out = "    faces:\n";
  for (std::size_t i = 0; i < c.faces.size();) {
    std::string names;
    std::size_t j = i;
    for (; j < c.faces.size() && c.faces[j].outward_plus_z == c.faces[i].outward_plus_z; ++j) {
      names += (j > i ? ", " : "") + yaml_quote(m.bodies[c.faces[j].body].name);
    }
    out += fmt::format("      - {{bodies: [{}], outward: {}}}\n", names,
                       c.faces[i].outward_plus_z ? "+z" : "-z");
    i = j;
  }
  return out;
}

std::string gas(const ChamberDef& c) {
  if (c.gas == GasModel::Prescribed) {
    const PressureDef& p = c.prescribed;
    if (p.at.empty())
      return fmt::format("    gas: prescribed\n    pressure: {}\n", yaml_number(p.pressure));
    return fmt::format(
        "    gas: prescribed\n    table: {{versus: {}, at: {}, pressure: {}}}   # s or -, Pa\n",
        p.versus == PressureVersus::Time ? "time" : "load_scale", numbers(p.at),
        numbers(p.pressures));
  }
  std::string out = fmt::format(
      "    gas: {}\n    gas_constant: {}   # J/(kg K)\n    gamma: {}\n    temperature: {}   # K\n"
      "    initial_pressure: {}   # Pa\n",
      c.gas == GasModel::Isothermal ? "isothermal" : "adiabatic", yaml_number(c.gas_constant),
      yaml_number(c.gamma), yaml_number(c.temperature), yaml_number(c.initial_pressure));
  if (!c.inflow.at.empty()) {
    out += fmt::format("    inflow: {{at: {}, mass_flow: {}, temperature: {}}}   # s, kg/s, K\n",
                       numbers(c.inflow.at), numbers(c.inflow.mass_flow),
                       numbers(c.inflow.temperature));
  }
  if (!c.vents.empty()) out += "    vents:   # m^2, -, Pa\n";
  for (const VentDef& v : c.vents) {
    out += fmt::format("      - {{area: {}, discharge_coefficient: {}, ambient_pressure: {}}}\n",
                       yaml_number(v.area), yaml_number(v.discharge_coefficient),
                       yaml_number(v.ambient_pressure));
  }
  return out;
}

}  // namespace

std::string chambers_section(const Model& m) {
  if (m.chambers.empty()) return "";
  std::string out = "chambers:\n";
  for (const ChamberDef& c : m.chambers) {
    out += fmt::format("  - name: {}\n", yaml_quote(c.name)) + faces(m, c);
    if (!c.end_plates.empty())
      out += "    end_plates:   # m, counter-clockwise seen from outside\n";
    for (const auto& plate : c.end_plates) {
      std::string corners;
      for (std::size_t k = 0; k < plate.size(); ++k)
        corners += (k ? ", " : "") + yaml_vector(plate[k]);
      out += fmt::format("      - [{}]\n", corners);
    }
    if (c.cap_open_ends) out += "    cap_open_ends: true\n";
    out += gas(c);
  }
  return out;
}

}  // namespace finseg
