// The plot of a sweep's table (docs/sweep.md): the first output against the first
// parameter, one line per combination of the other parameters.
#pragma once

#include <optional>
#include <vector>

#include "sweep/sweep_table.hpp"
#include "writers/plot.hpp"

namespace finseg {

/// The plot of the first numeric output against the first parameter (or the case number
/// where that is not a number), over the `ok` cases; nullopt when no case has a number to
/// plot.
std::optional<PlotSpec> sweep_plot_spec(const SweepSpec& spec,
                                        const std::vector<std::vector<Override>>& cases,
                                        const std::vector<SweepCaseResult>& results);

}  // namespace finseg
