#include "model/pressure_def.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"

namespace finseg {
namespace {

void check_pressure(double p, const std::string& source, const std::string& field) {
  if (!std::isfinite(p) || p < 0) {
    throw InputError(source, field, fmt::format("{} Pa; allowed range >= 0 Pa", p));
  }
}

void check_table(const PressureDef& d, const std::string& source, const std::string& f) {
  if (d.at.size() != d.pressures.size()) {
    throw InputError(source, f + ".pressure",
                     fmt::format("{} values for {} abscissae; give one per entry of 'at'",
                                 d.pressures.size(), d.at.size()));
  }
  for (std::size_t j = 0; j < d.at.size(); ++j) {
    const std::string fj = fmt::format("{}.at[{}]", f, j);
    if (!std::isfinite(d.at[j])) throw InputError(source, fj, "must be finite");
    if (j > 0 && !(d.at[j] > d.at[j - 1])) {
      throw InputError(
          source, fj,
          fmt::format("{} after {}; the table must be strictly ascending", d.at[j], d.at[j - 1]));
    }
    check_pressure(d.pressures[j], source, fmt::format("{}.pressure[{}]", f, j));
  }
}

}  // namespace

void validate_pressures(const std::vector<PressureDef>& defs, int num_bodies,
                        const std::string& source) {
  for (std::size_t i = 0; i < defs.size(); ++i) {
    const PressureDef& d = defs[i];
    const std::string f = fmt::format("pressures[{}]", i);
    if (d.bodies.empty()) throw InputError(source, f + ".bodies", "acts on no body");
    for (int b : d.bodies) {
      if (b < 0 || b >= num_bodies) {
        throw InputError(source, f + ".bodies",
                         fmt::format("body index {} out of range [0, {})", b, num_bodies));
      }
    }
    validate_pressure_value(d, source, f);
  }
}

void validate_pressure_value(const PressureDef& d, const std::string& source,
                             const std::string& field) {
  if (d.at.empty() && d.pressures.empty()) {
    check_pressure(d.pressure, source, field + ".pressure");
  } else {
    check_table(d, source, field);
  }
}

}  // namespace finseg
