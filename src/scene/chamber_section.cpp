// The `chambers:` section of a scene file (docs/scene.md, docs/gas.md): closed volumes of
// segment faces and fixed end plates, and the gas inside. Numbers are range-checked here;
// table order and the model's body indices by validate_chambers, the geometry (closed,
// outward, vents smaller than the chamber) by prepare_chambers.
#include <fmt/format.h>

#include "scene/scene_parts.hpp"

namespace finseg {
namespace {

std::vector<ChamberFace> read_faces(const Fields& f, const Model& m) {
  const auto items = sequence(f.node("faces"), f.context("faces"), "faces");
  if (items.empty()) f.fail("faces", "required: a list of {bodies | panels, outward: +z | -z}");
  std::vector<ChamberFace> out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Fields g(items[i], {f.context().file, item_field(f.field("faces"), i)},
                   {"panels", "bodies", "outward"});
    const bool plus = plus_z_side(g, "outward", "the side of the body frame facing out of the gas");
    for (const int b : selected_bodies(g, m)) out.push_back({b, plus});
  }
  return out;
}

std::vector<std::vector<Vec3>> read_plates(const Fields& f) {
  std::vector<std::vector<Vec3>> out;
  const auto plates = sequence(f.node("end_plates"), f.context("end_plates"), "end plates");
  for (std::size_t p = 0; p < plates.size(); ++p) {
    const std::string fp = item_field(f.field("end_plates"), p);
    const auto corners = sequence(plates[p], {f.context().file, fp}, "vertices [x, y, z] (m)");
    if (corners.size() < 3) {
      throw InputError(f.context().file, fp,
                       fmt::format("{} vertices; a plate needs at least 3 [x, y, z] (m), "
                                   "counter-clockwise seen from outside",
                                   corners.size()));
    }
    std::vector<Vec3> plate;
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const std::string fk = item_field(fp, k);
      if (!corners[k].IsSequence() || corners[k].size() != 3) {
        throw InputError(f.context().file, fk, "must be a list of three numbers [x, y, z] (m)");
      }
      Vec3 x;
      for (int i = 0; i < 3; ++i) {
        x[i] =
            read_number_at(corners[k][i], {f.context().file, item_field(fk, i)}, any_finite("m"));
      }
      plate.push_back(x);
    }
    out.push_back(plate);
  }
  return out;
}

GasModel read_gas_model(const Fields& f) {
  const std::string gas = f.required_word("gas");
  if (gas == "prescribed") return GasModel::Prescribed;
  if (gas == "isothermal") return GasModel::Isothermal;
  if (gas == "adiabatic") return GasModel::Adiabatic;
  f.fail("gas", "'" + gas + "'; allowed: prescribed, isothermal, adiabatic");
}

InflowDef read_inflow(const Fields& f) {
  const Fields t(f.node("inflow"), f.context("inflow"), {"at", "mass_flow", "temperature"});
  if (!t.has("at") || !t.has("mass_flow") || !t.has("temperature")) {
    t.fail("at", "required: at: [..] s, mass_flow: [..] kg/s, temperature: [..] K");
  }
  InflowDef in;
  in.at = t.numbers("at", any_finite("s"));
  in.mass_flow = t.numbers("mass_flow", non_negative("kg/s"));
  in.temperature = t.numbers("temperature", positive("K"));
  if (in.at.size() < 2) t.fail("at", "the inflow table needs at least two rows");
  return in;
}

std::vector<VentDef> read_vents(const Fields& f) {
  std::vector<VentDef> out;
  const auto items = sequence(f.node("vents"), f.context("vents"), "vents");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Fields v(items[i], {f.context().file, item_field(f.field("vents"), i)},
                   {"area", "discharge_coefficient", "ambient_pressure"});
    VentDef d;
    d.area = v.number("area", positive("m^2"));
    d.discharge_coefficient =
        v.number("discharge_coefficient", d.discharge_coefficient, interval(0, 1, true, false));
    d.ambient_pressure = v.number("ambient_pressure", d.ambient_pressure, non_negative("Pa"));
    out.push_back(d);
  }
  return out;
}

void read_gas(const Fields& f, ChamberDef& c) {
  c.gas = read_gas_model(f);
  if (c.gas == GasModel::Prescribed) {
    for (const char* key :
         {"gas_constant", "gamma", "temperature", "initial_pressure", "inflow", "vents"}) {
      if (f.has(key)) f.fail(key, "not used by gas: prescribed (use isothermal or adiabatic)");
    }
    if (f.has("pressure") == f.has("table")) {
      f.fail("pressure",
             "gas: prescribed needs either pressure: P (Pa) or table: {versus, at, "
             "pressure}");
    }
    if (f.has("pressure")) {
      c.prescribed.pressure = f.number("pressure", non_negative("Pa"));
    } else {
      read_pressure_table(f, c.prescribed);
    }
    return;
  }
  for (const char* key : {"pressure", "table"}) {
    if (f.has(key)) f.fail(key, "only for gas: prescribed (an ideal gas finds its own pressure)");
  }
  c.gas_constant = f.number("gas_constant", c.gas_constant, positive("J/(kg K)"));
  c.gamma = f.number("gamma", c.gamma, interval(1, 3, true, false));
  c.temperature = f.number("temperature", c.temperature, positive("K"));
  c.initial_pressure = f.number("initial_pressure", c.initial_pressure, non_negative("Pa"));
  if (f.has("inflow")) c.inflow = read_inflow(f);
  c.vents = read_vents(f);
}

}  // namespace

void read_chambers(const Fields& root, Model& m) {
  const auto items = sequence(root.node("chambers"), root.context("chambers"), "chambers");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Fields f(items[i], {root.context().file, item_field("chambers", i)},
                   {"name", "faces", "end_plates", "cap_open_ends", "gas", "pressure", "table",
                    "gas_constant", "gamma", "temperature", "initial_pressure", "inflow", "vents"});
    ChamberDef c;
    c.name = f.word("name", fmt::format("chamber{}", i + 1));
    for (const ChamberDef& other : m.chambers) {
      if (other.name == c.name) f.fail("name", "'" + c.name + "' is used twice; names must differ");
    }
    c.faces = read_faces(f, m);
    c.end_plates = read_plates(f);
    c.cap_open_ends = f.flag("cap_open_ends", false);
    read_gas(f, c);
    m.chambers.push_back(c);
  }
}

}  // namespace finseg
