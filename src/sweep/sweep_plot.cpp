#include "sweep/sweep_plot.hpp"

#include <charconv>
#include <map>
#include <string>

namespace finseg {
namespace {

std::optional<double> number_of(const std::string& text) {
  double x = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return x;
}

bool all_numbers(const SweepParameter& p) {
  for (const std::string& v : p.values) {
    if (!number_of(v)) return false;
  }
  return true;
}

}  // namespace

std::optional<PlotSpec> sweep_plot_spec(const SweepSpec& spec,
                                        const std::vector<std::vector<Override>>& cases,
                                        const std::vector<SweepCaseResult>& results) {
  if (spec.outputs.empty()) return std::nullopt;
  const std::string& y_key = spec.outputs[0];
  const bool by_value = all_numbers(spec.parameters[0]);
  std::map<std::string, PlotSeries> lines;  // by the other parameters' values
  std::vector<std::string> order;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const nlohmann::json& s = results[i].summary;
    if (s.is_null() || s.value("status", std::string()) != "ok") continue;
    const nlohmann::json y = summary_value(s, y_key);
    if (!y.is_number()) continue;
    std::string label;
    for (std::size_t k = 1; k < cases[i].size(); ++k) {
      label += (k > 1 ? ", " : "") + cases[i][k].path + " = " + cases[i][k].value;
    }
    if (!lines.count(label)) {
      order.push_back(label);
      lines[label].title = label.empty() ? y_key : label;
      lines[label].style = "linespoints";
    }
    PlotSeries& line = lines[label];
    line.x.push_back(by_value ? *number_of(cases[i][0].value) : static_cast<double>(i + 1));
    line.y.push_back(y.get<double>());
  }
  if (lines.empty()) return std::nullopt;
  PlotSpec p;
  p.title = "sweep: " + y_key;
  p.x_label = by_value ? spec.parameters[0].path : "case";
  p.y_label = y_key;
  for (const std::string& label : order) p.series.push_back(lines[label]);
  return p;
}

}  // namespace finseg
