#include "elements/gas_flow.hpp"

#include <algorithm>
#include <cmath>

namespace finseg {
namespace {

double lerp(double x0, double x1, double y0, double y1, double x) {
  return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
}

}  // namespace

InflowIntegral integrate_inflow(const InflowDef& in, double t0, double t1, double cp) {
  InflowIntegral sum;
  for (std::size_t j = 1; j < in.at.size(); ++j) {
    const double a = std::max(t0, in.at[j - 1]), b = std::min(t1, in.at[j]);
    if (!(b > a)) continue;
    const auto mdot = [&](double t) {
      return lerp(in.at[j - 1], in.at[j], in.mass_flow[j - 1], in.mass_flow[j], t);
    };
    const auto temp = [&](double t) {
      return lerp(in.at[j - 1], in.at[j], in.temperature[j - 1], in.temperature[j], t);
    };
    const double m = 0.5 * (a + b);
    sum.mass += 0.5 * (b - a) * (mdot(a) + mdot(b));
    // Simpson's rule: exact for the product of two linear functions.
    sum.enthalpy +=
        cp * (b - a) / 6 * (mdot(a) * temp(a) + 4 * mdot(m) * temp(m) + mdot(b) * temp(b));
  }
  return sum;
}

double total_inflow_mass(const InflowDef& in) {
  if (in.at.empty()) return 0;
  return integrate_inflow(in, in.at.front(), in.at.back(), 0).mass;
}

double vent_mass_flow(const VentDef& v, double p, double T, double R, double g) {
  if (!(p > v.ambient_pressure) || !(T > 0)) return 0;
  const double r = v.ambient_pressure / p;
  const double critical = std::pow(2 / (g + 1), g / (g - 1));
  const double a = v.discharge_coefficient * v.area * p / std::sqrt(R * T);
  if (r <= critical) return a * std::sqrt(g) * std::pow(2 / (g + 1), (g + 1) / (2 * (g - 1)));
  return a * std::sqrt(2 * g / (g - 1) * (std::pow(r, 2 / g) - std::pow(r, (g + 1) / g)));
}

}  // namespace finseg
