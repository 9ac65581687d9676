#include "writers/unfolding_outputs.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "writers/json_numbers.hpp"

namespace finseg {
namespace {

std::string number_or_empty(double v) {
  return std::isfinite(v) ? fmt::format("{:.12g}", v) : "";
}

}  // namespace

std::string unfolding_order_file(const std::string& probe) {
  return probe + "_order.csv";
}

std::string unfolding_map_file(const std::string& probe) {
  return probe + "_map.png";
}

std::string unfolding_order_csv(const std::vector<LineOpening>& order, const std::string& x) {
  std::string out = fmt::format(
      "rank,line,start_deg,target_deg,final_deg,final_opening,half_open_{},open_90_{},flat_x_m,"
      "flat_y_m\n",
      x, x);
  for (std::size_t i = 0; i < order.size(); ++i) {
    const LineOpening& o = order[i];
    out += fmt::format("{},{},{:.12g},{:.12g},{:.12g},{:.12g},{},{},{},{}\n",
                       std::isfinite(o.half_open_at) ? std::to_string(i + 1) : "", o.name,
                       o.start_deg, o.target_deg, o.final_deg, o.final_opening,
                       number_or_empty(o.half_open_at), number_or_empty(o.open_at),
                       number_or_empty(o.mid_M.x()), number_or_empty(o.mid_M.y()));
  }
  return out;
}

nlohmann::json unfolding_summary(const std::string& probe, std::size_t lines,
                                 const std::vector<LineOpening>& order,
                                 const std::vector<std::vector<double>>& rows) {
  nlohmann::json first = nlohmann::json::array();
  double all = order.empty() ? NAN : -INFINITY;
  for (const LineOpening& o : order) {
    if (std::isfinite(o.half_open_at) && first.size() < 10) {
      first.push_back({{"line", o.name}, {"half_open_at", o.half_open_at}});
    }
    all = std::max(all, std::isfinite(o.half_open_at) ? o.half_open_at : INFINITY);
  }
  return {{"lines", lines},
          {"folded_lines", order.size()},
          {"half_open_at_end", rows.empty() ? 0 : static_cast<int>(rows.back()[1])},
          {"first_half_open", first},
          {"all_half_open_at", or_null(all)},
          {"order_file", unfolding_order_file(probe)}};
}

PlotSpec unfolding_curve_plot(const std::string& title, const std::string& probe,
                              const std::vector<std::vector<double>>& rows, std::size_t folded,
                              const FrameAxis& axis) {
  PlotSpec spec;
  spec.title = title + ": " + probe;
  spec.x_label = axis.label;
  spec.y_label = "folded lines [%]";
  PlotSeries half{"at least half open", {}, {}}, mean{"mean opening", {}, {}};
  for (const auto& r : rows) {
    half.x.push_back(axis.scale * r[0]);
    half.y.push_back(folded > 0 ? 100.0 * r[1] / static_cast<double>(folded) : 0.0);
    mean.x.push_back(axis.scale * r[0]);
    mean.y.push_back(100.0 * r[2]);
  }
  spec.series = {half, mean};
  return spec;
}

Curve unfolding_curve(const std::string& probe, const std::vector<std::vector<double>>& rows,
                      const FrameAxis& axis) {
  Curve c{axis.label, probe + " folds at least half open", {}, {}};
  for (const auto& r : rows) {
    c.x.push_back(axis.scale * r[0]);
    c.y.push_back(r[1]);
  }
  return c;
}

PlotSpec unfolding_map_plot(const std::string& title, const std::vector<UnfoldingLine>& lines,
                            const std::vector<LineOpening>& order, const FrameAxis& axis) {
  PlotSpec spec;
  spec.title = title + ": where the folds opened";
  spec.x_label = "flat sheet x [mm]";
  spec.y_label = "flat sheet y [mm]";
  spec.segment_label = "half open at: " + axis.label;
  spec.grey_label = "never half open";
  std::map<std::string, double> when;
  for (const LineOpening& o : order) when[o.name] = axis.scale * o.half_open_at;
  for (const UnfoldingLine& l : lines) {
    const auto it = when.find(l.name);
    if (it == when.end()) continue;  // not folded
    for (const auto& s : l.sides_M) {
      spec.segments.push_back(
          {1e3 * s[0].x(), 1e3 * s[0].y(), 1e3 * s[1].x(), 1e3 * s[1].y(), it->second});
    }
  }
  return spec;
}

}  // namespace finseg
