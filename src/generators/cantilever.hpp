// The paper's bending test (section 3.1): a strip clamped at x = 0, lying along +x, width
// along y, z up, loaded at its free edge. Used by `finseg gen cantilever`, the validation
// tests and the benchmarks.
#pragma once

#include "generators/sheet.hpp"
#include "model/model.hpp"

namespace finseg {

/// Parameters of the cantilever strip. SI units: m, Pa, kg/m^3, N, N m.
struct CantileverSpec {
  double length = 0.1;  ///< free length from the clamp to the tip
  double width = 0.02, thickness = 1e-4;
  double youngs_modulus = 4e9, poisson_ratio = 0.3, density = 800;
  int segments = 16;               ///< cells along the free length
  int segments_across = 1;         ///< rows across the width
  Vec3 tip_force = Vec3::Zero();   ///< dead load at the free edge, world frame, N
  Vec3 tip_moment = Vec3::Zero();  ///< dead moment at the free edge, world frame, N m
  bool gravity = false;            ///< 9.81 m/s^2 along -z
  double damping_time = 0;         ///< stiffness-proportional damping, s
};

/// Checks the spec; throws InputError naming the field and the allowed range.
void validate(const CantileverSpec& spec, const std::string& source = "<api>");

/// The sheet part of the cantilever (clamped half cell at s = 0).
SheetSpec cantilever_sheet(const CantileverSpec& spec);

/// The whole model: the sheet, the tip load shared equally by the free-edge bodies of all
/// rows (applied at the middle of each row's free edge), gravity, and the probe `tip` at
/// the mid-point of the free edge.
Model build_cantilever_model(const CantileverSpec& spec);

/// Bending rigidity E w t^3 / 12 of the strip, N m^2.
double bending_rigidity(const CantileverSpec& spec);

}  // namespace finseg
