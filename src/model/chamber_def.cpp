#include "model/chamber_def.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"

namespace finseg {
namespace {

void check_range(bool ok, double v, const std::string& source, const std::string& field,
                 const std::string& allowed) {
  if (!ok || !std::isfinite(v)) {
    throw InputError(source, field, fmt::format("{}; allowed: {}", v, allowed));
  }
}

void check_inflow(const InflowDef& in, const std::string& source, const std::string& f) {
  if (in.at.empty()) return;
  if (in.mass_flow.size() != in.at.size() || in.temperature.size() != in.at.size()) {
    throw InputError(source, f + ".mass_flow",
                     fmt::format("{} mass flows and {} temperatures for {} times; give one per "
                                 "entry of 'at'",
                                 in.mass_flow.size(), in.temperature.size(), in.at.size()));
  }
  for (std::size_t j = 0; j < in.at.size(); ++j) {
    const std::string fj = fmt::format("{}.at[{}]", f, j);
    if (!std::isfinite(in.at[j])) throw InputError(source, fj, "must be finite (s)");
    if (j > 0 && !(in.at[j] > in.at[j - 1])) {
      throw InputError(source, fj,
                       fmt::format("{} s after {} s; the times must be strictly ascending",
                                   in.at[j], in.at[j - 1]));
    }
    check_range(in.mass_flow[j] >= 0, in.mass_flow[j], source,
                fmt::format("{}.mass_flow[{}]", f, j), ">= 0 kg/s");
    check_range(in.temperature[j] > 0, in.temperature[j], source,
                fmt::format("{}.temperature[{}]", f, j), "> 0 K");
  }
}

void check_gas(const ChamberDef& c, const std::string& source, const std::string& f) {
  if (c.gas == GasModel::Prescribed) {
    validate_pressure_value(c.prescribed, source, f);
    if (!c.inflow.at.empty() || !c.vents.empty()) {
      throw InputError(source, f + ".gas",
                       "a prescribed pressure takes no inflow or vents (use isothermal or "
                       "adiabatic)");
    }
    return;
  }
  check_range(c.gas_constant > 0, c.gas_constant, source, f + ".gas_constant", "> 0 J/(kg K)");
  check_range(c.gamma > 1 && c.gamma <= 3, c.gamma, source, f + ".gamma", "(1, 3]");
  check_range(c.temperature > 0, c.temperature, source, f + ".temperature", "> 0 K");
  check_range(c.initial_pressure >= 0, c.initial_pressure, source, f + ".initial_pressure",
              ">= 0 Pa");
  check_inflow(c.inflow, source, f + ".inflow");
  for (std::size_t v = 0; v < c.vents.size(); ++v) {
    const VentDef& d = c.vents[v];
    const std::string fv = fmt::format("{}.vents[{}]", f, v);
    check_range(d.area > 0, d.area, source, fv + ".area", "> 0 m^2");
    check_range(d.discharge_coefficient > 0 && d.discharge_coefficient <= 1,
                d.discharge_coefficient, source, fv + ".discharge_coefficient", "(0, 1]");
    check_range(d.ambient_pressure >= 0, d.ambient_pressure, source, fv + ".ambient_pressure",
                ">= 0 Pa");
  }
}

}  // namespace

void validate_chambers(const std::vector<ChamberDef>& defs, int num_bodies,
                       const std::string& source) {
  for (std::size_t i = 0; i < defs.size(); ++i) {
    const ChamberDef& c = defs[i];
    const std::string f = fmt::format("chambers[{}]", i);
    if (c.faces.empty()) throw InputError(source, f + ".faces", "a chamber needs segment faces");
    for (const ChamberFace& face : c.faces) {
      if (face.body < 0 || face.body >= num_bodies) {
        throw InputError(source, f + ".faces",
                         fmt::format("body index {} out of range [0, {})", face.body, num_bodies));
      }
    }
    for (std::size_t p = 0; p < c.end_plates.size(); ++p) {
      if (c.end_plates[p].size() < 3) {
        throw InputError(source, fmt::format("{}.end_plates[{}]", f, p),
                         "a plate needs at least 3 vertices");
      }
    }
    check_gas(c, source, f);
  }
}

}  // namespace finseg
