#include "generators/zigzag_conditions.hpp"

#include <fmt/format.h>
#include <cmath>

#include "core/error.hpp"

namespace finseg {
namespace {

void check_layers(const std::vector<Layer>& layers) {
  if (layers.empty()) throw InputError("<api>", "layers", "need at least one layer");
  for (const Layer& l : layers) {
    if (!(l.thickness > 0) || !(l.modulus >= 0) || !(l.density >= 0)) {
      throw InputError("<api>", "layers",
                       "thickness must be > 0 m, modulus >= 0 Pa and density >= 0 kg/m^3");
    }
  }
}

}  // namespace

double laminate_bending_rigidity(const std::vector<Layer>& layers, double width) {
  check_layers(layers);
  double z = 0, EA = 0, EAz = 0;  // per unit width
  for (const Layer& l : layers) {
    EA += l.modulus * l.thickness;
    EAz += l.modulus * l.thickness * (z + 0.5 * l.thickness);
    z += l.thickness;
  }
  if (!(EA > 0)) throw InputError("<api>", "layers", "at least one layer must carry stress");
  const double z_n = EAz / EA;  // neutral axis
  double EI = 0;
  z = 0;
  for (const Layer& l : layers) {
    const double t = l.thickness, d = z + 0.5 * t - z_n;
    EI += l.modulus * (t * t * t / 12 + t * d * d);
    z += t;
  }
  return EI * width;
}

double laminate_areal_mass(const std::vector<Layer>& layers) {
  check_layers(layers);
  double m = 0;
  for (const Layer& l : layers) m += l.density * l.thickness;
  return m;
}

Layer paper_layer() {
  return {1.0e-4, 4.0e9, 800.0};  // 80 g/m^2 at 0.1 mm
}

std::vector<Layer> taped_paper_layers() {
  return {paper_layer(), {2.0e-5, 0.0, 1050.0}, {5.0e-5, 2.0e9, 905.0}};
}

ZigzagSpec paper_condition(int n) {
  if (n < 1 || n > 4) {
    throw InputError("<api>", "condition", fmt::format("{}; Table 1 has conditions 1..4", n));
  }
  ZigzagSpec s;
  const Layer paper = paper_layer();
  s.thickness = paper.thickness;
  s.youngs_modulus = paper.modulus;
  s.density = paper.density;
  s.fold_angle = (n <= 2 ? 80.0 : 83.0) * kDegToRad;
  if (n % 2 == 0) {
    // Tape on the panels, not on the creases: panel bending rigidity and mass change, the
    // crease law does not. The sheet keeps the paper's thickness; its density carries the
    // tape's mass.
    const std::vector<Layer> taped = taped_paper_layers();
    s.overrides.bending_rigidity = laminate_bending_rigidity(taped, s.width);
    s.density = laminate_areal_mass(taped) / s.thickness;
  }
  return s;
}

const char* paper_condition_label(int n) {
  static const char* const labels[] = {"80 deg, plain", "80 deg, taped", "83 deg, plain",
                                       "83 deg, taped"};
  if (n < 1 || n > 4) return "unknown";
  return labels[n - 1];
}

}  // namespace finseg
