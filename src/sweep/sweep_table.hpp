// The table of a sweep: one row per case, in case order, with the parameter values, the
// run's status and the chosen summary.json values (docs/sweep.md).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/sweep_spec.hpp"

namespace finseg {

/// What one case left: its summary.json (null when the run wrote none) and, for a case that
/// failed before writing one, the reason.
struct SweepCaseResult {
  nlohmann::json summary;
  std::string failure;
};

/// The value at a dotted key of a summary ("probes.gauge.deployment_peak_force_N"), or null.
nlohmann::json summary_value(const nlohmann::json& summary, const std::string& key);

/// CSV: case, one column per parameter (its path), status, one column per output key, message.
/// Numbers with 10 significant digits, empty cells for missing values.
std::string sweep_table_csv(const SweepSpec& spec, const std::vector<std::vector<Override>>& cases,
                            const std::vector<SweepCaseResult>& results);

}  // namespace finseg
