// Pressure loads on segment faces (issue 13, item 1): which faces, which side, how much.
#pragma once

#include <string>
#include <vector>

namespace finseg {

/// Which face of a segment's mid-surface the pressure pushes on. PlusZ: the fluid is on
/// the body's +z side and pushes the segment towards -z_B; MinusZ: the reverse.
enum class PressureSide { PlusZ, MinusZ };

/// What a pressure table is indexed by.
enum class PressureVersus { Time, LoadScale };

/// A uniform pressure on the mid-surface polygons of some bodies, as a
/// follower load. Constant: p = load_scale * pressure. Table: p interpolated linearly in
/// (at, pressure), held at the end values outside it, not scaled by the load scale.
struct PressureDef {
  std::string name;
  std::vector<int> bodies;  ///< 0-based body indices
  PressureSide side = PressureSide::PlusZ;
  double pressure = 0;  ///< Pa, constant pressure (when `at` is empty)
  PressureVersus versus = PressureVersus::Time;
  std::vector<double> at;         ///< table abscissae: s (time) or - (load scale), ascending
  std::vector<double> pressures;  ///< Pa, one per entry of `at`
};

/// Checks pressures (finite, >= 0), tables (same lengths, strictly ascending finite
/// abscissae) and body indices of `defs`; throws InputError naming `source` and the field.
void validate_pressures(const std::vector<PressureDef>& defs, int num_bodies,
                        const std::string& source);

/// Checks the value part of `d` (constant or table, as validate_pressures does), naming
/// `field` (e.g. "chambers[0]").
void validate_pressure_value(const PressureDef& d, const std::string& source,
                             const std::string& field);

}  // namespace finseg
