// What an unfolding probe leaves besides its table (docs/scene.md, "unfolding"): the folded
// lines in the order they opened (CSV and summary.json), the opening against the run's
// abscissa, and a map of the flat sheet with every crease coloured by when it opened.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "probes/unfolding.hpp"
#include "writers/frames.hpp"
#include "writers/html_animation.hpp"
#include "writers/plot.hpp"

namespace finseg {

/// "<probe>_order.csv" and "<probe>_map.png" of an unfolding probe.
std::string unfolding_order_file(const std::string& probe);
std::string unfolding_map_file(const std::string& probe);

/// The order as CSV: rank (1 = first half open; empty for a line never half open), line,
/// start_deg, target_deg, final_deg, final_opening, half_open_<x>, open_90_<x> (the
/// abscissa `x`'s name and unit, empty where never reached), flat_x_m, flat_y_m.
std::string unfolding_order_csv(const std::vector<LineOpening>& order, const std::string& x);

/// For summary.json: lines, folded_lines, half_open_at_end, first_half_open (the first ten:
/// line and abscissa), all_half_open_at (null unless every folded line came half open),
/// order_file.
nlohmann::json unfolding_summary(const std::string& probe, std::size_t lines,
                                 const std::vector<LineOpening>& order,
                                 const std::vector<std::vector<double>>& rows);

/// The share of folded lines at least half open and their mean opening, %, against the
/// run's abscissa (as `axis` shows it).
PlotSpec unfolding_curve_plot(const std::string& title, const std::string& probe,
                              const std::vector<std::vector<double>>& rows, std::size_t folded,
                              const FrameAxis& axis);

/// Count of folded lines at least half open against the abscissa (the HTML page's chart).
Curve unfolding_curve(const std::string& probe, const std::vector<std::vector<double>>& rows,
                      const FrameAxis& axis);

/// The flat sheet's folded lines coloured by when they came half open (mm; grey: never).
/// No segments when the model's bodies have no flat placement.
PlotSpec unfolding_map_plot(const std::string& title, const std::vector<UnfoldingLine>& lines,
                            const std::vector<LineOpening>& order, const FrameAxis& axis);

}  // namespace finseg
