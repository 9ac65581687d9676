// Numbers into summary.json: JSON has no NaN or infinity.
#pragma once

#include <cmath>

#include <nlohmann/json.hpp>

namespace finseg {

/// `v`, or null where it is not finite (not found, never reached).
inline nlohmann::json or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

}  // namespace finseg
