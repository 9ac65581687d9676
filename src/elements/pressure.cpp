#include "elements/pressure.hpp"

#include <algorithm>

#include "elements/assembler.hpp"

namespace finseg {
namespace {

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  const auto hi = std::upper_bound(x.begin(), x.end(), at);
  const std::size_t j = static_cast<std::size_t>(hi - x.begin());
  const double w = (at - x[j - 1]) / (x[j] - x[j - 1]);
  return (1 - w) * y[j - 1] + w * y[j];
}

}  // namespace

double pressure_now(const PressureDef& def, double t, double load_scale) {
  if (def.at.empty()) return load_scale * def.pressure;
  return interpolate(def.at, def.pressures, def.versus == PressureVersus::Time ? t : load_scale);
}

Vec3 pressure_direction_B(PressureSide side) {
  return side == PressureSide::PlusZ ? Vec3(0, 0, -1) : Vec3(0, 0, 1);
}

double largest_pressure_force(const Model& model) {
  double f = 0;
  for (const PressureDef& def : model.pressures) {
    double p = def.pressure;
    for (double q : def.pressures) p = std::max(p, q);
    for (int b : def.bodies) f = std::max(f, p * segment_area(model.bodies[b]));
  }
  return f;
}

void add_face_pressure(const Model& model, int body, PressureSide side, double p, Assembler& as) {
  const Vec3 f_B = p * segment_area(model.bodies[body]) * pressure_direction_B(side);
  as.single(body, [&](const auto& A, auto& w) {
    using T = typename std::decay_t<decltype(A.p_W)>::Scalar;
    // Uniform pressure on a flat polygon: the resultant acts at its centroid, which
    // is the body's centroid (mid-surface), so it has no moment about it.
    w.f_W += A.R_WB * f_B.cast<T>();
    return T(0);
  });
}

void add_pressure_loads(const Model& model, const State& state, Assembler& as) {
  for (const PressureDef& def : model.pressures) {
    const double p = pressure_now(def, state.t, state.load_scale);
    if (p == 0) continue;
    for (int b : def.bodies) add_face_pressure(model, b, def.side, p, as);
  }
}

}  // namespace finseg
