#include "comparison/compare.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "core/cubic_spline.hpp"
#include "core/error.hpp"
#include "core/text.hpp"
#include "probes/deployment_peak.hpp"
#include "writers/atomic_write.hpp"
#include "writers/plot.hpp"

namespace finseg {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() > suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Index of the wanted column and its unit factor to SI.
struct Column {
  int index = -1;
  double factor = 1;
};

// A column's unit from its name's suffix; 0 when it has none of `units`.
double unit_factor(const std::string& name,
                   const std::vector<std::pair<std::string, double>>& units) {
  for (const auto& [suffix, factor] : units) {
    if (ends_with(name, suffix)) return factor;
  }
  return 0;
}

// The wanted column (by name, or the first whose name carries one of `units`; else the
// first column not in `taken`) and its factor to SI; a column without a unit suffix is read
// in `default_unit` (units[0]) and a note says so.
Column find_column(const std::vector<std::string>& header, const std::string& wanted,
                   const std::vector<std::pair<std::string, double>>& units, int taken,
                   ForceCurve& c, const char* what) {
  int index = -1;
  for (size_t i = 0; i < header.size() && index < 0; ++i) {
    const bool match = wanted.empty() ? unit_factor(header[i], units) > 0 : header[i] == wanted;
    if (match) index = static_cast<int>(i);
  }
  if (index < 0 && !wanted.empty()) {
    std::string names;
    for (size_t i = 0; i < header.size(); ++i) names += (i ? ", " : "") + header[i];
    throw InputError(c.source, "header",
                     fmt::format("no column '{}' among the columns [{}]", wanted, names));
  }
  for (size_t i = 0; i < header.size() && index < 0; ++i) {
    if (static_cast<int>(i) != taken) index = static_cast<int>(i);
  }
  if (index < 0) {
    throw InputError(c.source, "header",
                     fmt::format("no {} column: the header has {} column(s)", what, header.size()));
  }
  const double factor = unit_factor(header[index], units);
  if (factor > 0) return {index, factor};
  c.notes.push_back(fmt::format("column '{}' has no unit suffix: read as {} in {}", header[index],
                                what, units[0].first.substr(1)));
  return {index, units[0].second};
}

// Cells of one line; in a ';'-separated file a ',' is a decimal comma.
std::vector<std::string> cells_of(std::string line, bool semicolons) {
  if (semicolons) {
    std::replace(line.begin(), line.end(), ',', '.');
    std::replace(line.begin(), line.end(), ';', ',');
  }
  return split_csv_line(line);
}

// Values this large overflow the spline, the mean and the squared errors.
constexpr double kLargestValue = 1e100;

double read_value(const std::string& cell, double factor, const std::string& path, int line,
                  const std::string& column) {
  const std::string where = fmt::format("line {}, column {}", line, column);
  const double v = factor * parse_number(cell, path, where);
  if (!(std::abs(v) < kLargestValue)) {
    throw InputError(path, where,
                     fmt::format("'{}' is out of range; |value| must be below 1e100 (SI)", cell));
  }
  return v;
}

// Largest value and its abscissa.
std::pair<double, double> largest(const std::vector<double>& x, const std::vector<double>& y) {
  const size_t i = std::max_element(y.begin(), y.end()) - y.begin();
  return {y[i], x[i]};
}

// Every number of the comparison finite, or an InputError naming what overflowed.
void require_finite(const Comparison& c, const ForceCurve& sim,
                    const std::vector<ForceCurve>& runs) {
  const auto finite = [](const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
  };
  if (!finite(c.simulation)) throw InputError(sim.source, "values", "resampled curve overflows");
  for (size_t k = 0; k < runs.size(); ++k) {
    if (!finite(c.runs[k])) throw InputError(runs[k].source, "values", "resampled curve overflows");
  }
  if (!finite(c.mean) || !finite(c.stddev) || !finite(c.difference) ||
      !std::isfinite(c.rms_error) || !std::isfinite(c.peak_error)) {
    throw InputError(runs.front().source, "values",
                     "the comparison overflows or divides by a zero peak force (mean, spread, "
                     "rms or peak error not finite)");
  }
}

}  // namespace

std::vector<double> resample_curve(const ForceCurve& c, const std::vector<double>& x) {
  const CubicSpline s(c.x, c.force, SplineEnds::NotAKnot);
  std::vector<double> y;
  y.reserve(x.size());
  for (double xi : x) y.push_back(s.value(xi));
  return y;
}

MeasuredSpread measured_spread(const std::vector<ForceCurve>& runs, const std::vector<double>& x) {
  MeasuredSpread m;
  for (const ForceCurve& r : runs) m.runs.push_back(resample_curve(r, x));
  const size_t n = runs.size();
  for (size_t i = 0; i < x.size(); ++i) {
    double sum = 0, lo = INFINITY, hi = -INFINITY;
    for (const auto& r : m.runs) sum += r[i], lo = std::min(lo, r[i]), hi = std::max(hi, r[i]);
    const double mean = sum / n;
    double var = 0;
    for (const auto& r : m.runs) var += (r[i] - mean) * (r[i] - mean);
    m.mean.push_back(mean);
    m.stddev.push_back(n > 1 ? std::sqrt(var / (n - 1)) : 0.0);
    m.min.push_back(lo);
    m.max.push_back(hi);
  }
  return m;
}

ForceCurve read_force_curve(const std::string& path, const std::string& x_column,
                            const std::string& y_column) {
  std::istringstream in(read_text_file(path));  // BOM and CR line ends as everywhere
  ForceCurve c;
  c.source = path;
  Column cx, cy;
  size_t ncols = 0;
  std::string line;
  int number = 0;
  bool have_header = false, semicolons = false;
  while (std::getline(in, line)) {
    ++number;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (trim(line).empty()) continue;
    if (!have_header) semicolons = line.find(';') != std::string::npos;
    const std::vector<std::string> cells = cells_of(line, semicolons);
    if (!have_header) {
      if (std::all_of(cells.begin(), cells.end(), [](const std::string& cell) {
            char* end = nullptr;
            std::strtod(cell.c_str(), &end);
            return !cell.empty() && *end == '\0';
          })) {
        throw InputError(path, fmt::format("line {}", number),
                         "the first line holds numbers; a header line naming the columns "
                         "(e.g. pull_displacement_mm,force_N) must come first");
      }
      cx = find_column(cells, x_column, {{"_mm", 1e-3}, {"_m", 1.0}}, -1, c, "displacement");
      cy = find_column(cells, y_column, {{"_N", 1.0}, {"_mN", 1e-3}}, cx.index, c, "force");
      c.x_column = cells[cx.index];
      c.y_column = cells[cy.index];
      ncols = cells.size();
      have_header = true;
      continue;
    }
    if (cells.size() != ncols) {
      throw InputError(path, fmt::format("line {}", number),
                       fmt::format("{} values, the header has {} columns", cells.size(), ncols));
    }
    const double x = read_value(cells[cx.index], cx.factor, path, number, c.x_column);
    const double f = read_value(cells[cy.index], cy.factor, path, number, c.y_column);
    if (!c.x.empty() && !(x > c.x.back())) {
      throw InputError(path, fmt::format("line {}, column {}", number, c.x_column),
                       "displacement must increase strictly from row to row");
    }
    c.x.push_back(x);
    c.force.push_back(f);
  }
  if (!have_header) throw InputError(path, "header", "file has no header line");
  if (c.x.size() < 4) {
    throw InputError(path, "rows",
                     fmt::format("{} data rows; a cubic spline needs at least 4", c.x.size()));
  }
  return c;
}

Comparison compare_curves(const ForceCurve& sim, const std::vector<ForceCurve>& runs, int samples,
                          const CompareWindow& window) {
  if (runs.empty()) throw InputError("<compare>", "measurements", "need at least one");
  if (samples < 2) throw InputError("<compare>", "samples", "must be >= 2");
  double a = sim.x.front(), b = sim.x.back();
  for (const ForceCurve& r : runs) a = std::max(a, r.x.front()), b = std::min(b, r.x.back());
  if (!(b > a)) {
    throw InputError(runs.front().source, "displacement",
                     "the displacement ranges of the curves do not overlap");
  }
  if (!(std::min(b, window.hi) > std::max(a, window.lo))) {
    throw InputError("<compare>", "--window",
                     fmt::format("{:g} .. {:g} mm misses the common range {:g} .. {:g} mm",
                                 1e3 * window.lo, 1e3 * window.hi, 1e3 * a, 1e3 * b));
  }
  a = std::max(a, window.lo), b = std::min(b, window.hi);
  Comparison c;
  for (int i = 0; i < samples; ++i) c.x.push_back(a + (b - a) * i / (samples - 1));
  c.simulation = resample_curve(sim, c.x);
  MeasuredSpread m = measured_spread(runs, c.x);
  c.runs = std::move(m.runs);
  c.mean = std::move(m.mean);
  c.stddev = std::move(m.stddev);
  c.min = std::move(m.min);
  c.max = std::move(m.max);
  double sq = 0;
  for (size_t i = 0; i < c.x.size(); ++i) {
    const double d = c.simulation[i] - c.mean[i];
    c.difference.push_back(d);
    sq += d * d;
    if (std::abs(d) > c.max_error) c.max_error = std::abs(d), c.max_error_x = c.x[i];
  }
  c.rms_error = std::sqrt(sq / c.x.size());
  std::tie(c.sim_max, c.sim_max_x) = largest(c.x, c.simulation);
  std::tie(c.mean_max, c.mean_max_x) = largest(c.x, c.mean);
  const DeploymentPeak ps = find_deployment_peak(c.x, c.simulation, a, b);
  const DeploymentPeak pm = find_deployment_peak(c.x, c.mean, a, b);
  if (ps.found && pm.found) {
    c.peak_rule = "deployment";
    c.sim_peak = ps.force, c.sim_peak_x = ps.x, c.mean_peak = pm.force, c.mean_peak_x = pm.x;
  } else {
    c.peak_rule = "largest";
    c.sim_peak = c.sim_max, c.sim_peak_x = c.sim_max_x;
    c.mean_peak = c.mean_max, c.mean_peak_x = c.mean_max_x;
  }
  c.peak_error = (c.sim_peak - c.mean_peak) / c.mean_peak;
  require_finite(c, sim, runs);
  return c;
}

void write_comparison(const Comparison& c, const ForceCurve& sim,
                      const std::vector<ForceCurve>& runs, const std::string& dir, bool plot) {
  std::filesystem::create_directories(dir);
  std::string csv = "pull_displacement_mm,simulation_N";
  for (size_t k = 0; k < c.runs.size(); ++k) csv += fmt::format(",measurement{}_N", k + 1);
  csv += ",mean_N,stddev_N,min_N,max_N,difference_N\n";
  for (size_t i = 0; i < c.x.size(); ++i) {
    csv += fmt::format("{:.9g},{:.9g}", 1e3 * c.x[i], c.simulation[i]);
    for (const auto& r : c.runs) csv += fmt::format(",{:.9g}", r[i]);
    csv += fmt::format(",{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", c.mean[i], c.stddev[i], c.min[i],
                       c.max[i], c.difference[i]);
  }
  write_file_atomically(dir + "/comparison.csv", csv);
  nlohmann::json j;
  j["simulation_file"] = sim.source;
  for (const ForceCurve& r : runs) j["measurement_files"].push_back(r.source);
  nlohmann::json notes = nlohmann::json::array();
  for (const ForceCurve& r : runs) {
    for (const std::string& n : r.notes) notes.push_back(r.source + ": " + n);
  }
  for (const std::string& n : sim.notes) notes.push_back(sim.source + ": " + n);
  j["notes"] = notes;
  j["range_mm"] = {1e3 * c.x.front(), 1e3 * c.x.back()};
  j["samples"] = c.x.size();
  j["peak_rule"] = c.peak_rule;
  j["simulation_peak_force_N"] = c.sim_peak;
  j["simulation_peak_displacement_mm"] = 1e3 * c.sim_peak_x;
  j["mean_peak_force_N"] = c.mean_peak;
  j["mean_peak_displacement_mm"] = 1e3 * c.mean_peak_x;
  j["peak_force_error_percent"] = 100 * c.peak_error;
  j["simulation_max_force_N"] = c.sim_max;
  j["simulation_max_displacement_mm"] = 1e3 * c.sim_max_x;
  j["mean_max_force_N"] = c.mean_max;
  j["mean_max_displacement_mm"] = 1e3 * c.mean_max_x;
  j["rms_error_N"] = c.rms_error;
  j["max_error_N"] = c.max_error;
  j["max_error_displacement_mm"] = 1e3 * c.max_error_x;
  write_file_atomically(dir + "/comparison.json", j.dump(2) + "\n");
  if (!plot) return;
  PlotSpec p;
  p.title = fmt::format("Pull force: simulation vs {} measurements (peak error {:+.2f} %)",
                        runs.size(), 100 * c.peak_error);
  p.x_label = "pull displacement (mm)";
  p.y_label = "force (N)";
  std::vector<double> x_mm;
  for (double x : c.x) x_mm.push_back(1e3 * x);
  p.bands.push_back({"measured spread (min - max)", x_mm, c.min, c.max});
  p.series.push_back({"simulation", x_mm, c.simulation});
  for (size_t k = 0; k < c.runs.size(); ++k) {
    p.series.push_back({fmt::format("measurement {}", k + 1), x_mm, c.runs[k]});
  }
  p.series.push_back({"measured mean", x_mm, c.mean});
  p.series.push_back({"difference (simulation - mean)", x_mm, c.difference});
  const char* what = c.peak_rule == "deployment" ? "deployment peak" : "largest force";
  p.points.push_back(
      {1e3 * c.sim_peak_x, c.sim_peak, fmt::format("simulation {} {:.4g} N", what, c.sim_peak)});
  p.points.push_back({1e3 * c.mean_peak_x, c.mean_peak,
                      fmt::format("measured {} {:.4g} N", what, c.mean_peak), false});
  write_plot(dir + "/comparison.png", p);
}

}  // namespace finseg
