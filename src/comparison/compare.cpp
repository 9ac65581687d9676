#include "comparison/compare.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/cubic_spline.hpp"
#include "core/error.hpp"
#include "core/text.hpp"
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

Column find_column(const std::vector<std::string>& header, const std::string& wanted,
                   const std::vector<std::pair<std::string, double>>& units,
                   const std::string& path, const char* what) {
  std::string names;
  for (size_t i = 0; i < header.size(); ++i) {
    names += (i ? ", " : "") + header[i];
    const bool named = !wanted.empty() && header[i] == wanted;
    for (const auto& [suffix, factor] : units) {
      if (ends_with(header[i], suffix) && (named || wanted.empty())) {
        return {static_cast<int>(i), factor};
      }
    }
    if (named) {
      throw InputError(path, "header",
                       fmt::format("column '{}' has no unit suffix ({})", wanted, what));
    }
  }
  const std::string need =
      wanted.empty() ? fmt::format("a {} column", what) : fmt::format("column '{}'", wanted);
  throw InputError(path, "header", fmt::format("no {} among the columns [{}]", need, names));
}

std::vector<double> resample(const ForceCurve& c, const std::vector<double>& x) {
  const CubicSpline s(c.x, c.force, SplineEnds::NotAKnot);
  std::vector<double> y;
  y.reserve(x.size());
  for (double xi : x) y.push_back(s.value(xi));
  return y;
}

// Largest value and its abscissa.
std::pair<double, double> peak(const std::vector<double>& x, const std::vector<double>& y) {
  const size_t i = std::max_element(y.begin(), y.end()) - y.begin();
  return {y[i], x[i]};
}

}  // namespace

ForceCurve read_force_curve(const std::string& path, const std::string& x_column,
                            const std::string& y_column) {
  std::istringstream in(read_text_file(path));  // BOM and CR line ends as everywhere
  ForceCurve c;
  c.source = path;
  Column cx, cy;
  size_t ncols = 0;
  std::string line;
  int number = 0;
  bool have_header = false;
  while (std::getline(in, line)) {
    ++number;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (trim(line).empty()) continue;
    const std::vector<std::string> cells = split_csv_line(line);
    if (!have_header) {
      cx = find_column(cells, x_column, {{"_mm", 1e-3}, {"_m", 1.0}}, path,
                       "displacement (name ending in _mm or _m)");
      cy = find_column(cells, y_column, {{"_mN", 1e-3}, {"_N", 1.0}}, path,
                       "force (name ending in _N or _mN)");
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
    const double x = cx.factor * parse_number(cells[cx.index], path,
                                              fmt::format("line {}: {}", number, c.x_column));
    const double f = cy.factor * parse_number(cells[cy.index], path,
                                              fmt::format("line {}: {}", number, c.y_column));
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

Comparison compare_curves(const ForceCurve& sim, const std::vector<ForceCurve>& runs, int samples) {
  if (runs.empty()) throw InputError("<compare>", "measurements", "need at least one");
  if (samples < 2) throw InputError("<compare>", "samples", "must be >= 2");
  double a = sim.x.front(), b = sim.x.back();
  for (const ForceCurve& r : runs) a = std::max(a, r.x.front()), b = std::min(b, r.x.back());
  if (!(b > a)) {
    throw InputError(runs.front().source, "displacement",
                     "the displacement ranges of the curves do not overlap");
  }
  Comparison c;
  for (int i = 0; i < samples; ++i) c.x.push_back(a + (b - a) * i / (samples - 1));
  c.simulation = resample(sim, c.x);
  for (const ForceCurve& r : runs) c.runs.push_back(resample(r, c.x));
  const size_t n = runs.size();
  double sq = 0;
  for (size_t i = 0; i < c.x.size(); ++i) {
    double sum = 0, lo = INFINITY, hi = -INFINITY;
    for (const auto& r : c.runs) sum += r[i], lo = std::min(lo, r[i]), hi = std::max(hi, r[i]);
    const double mean = sum / n;
    double var = 0;
    for (const auto& r : c.runs) var += (r[i] - mean) * (r[i] - mean);
    c.mean.push_back(mean);
    c.stddev.push_back(n > 1 ? std::sqrt(var / (n - 1)) : 0.0);
    c.min.push_back(lo);
    c.max.push_back(hi);
    const double d = c.simulation[i] - mean;
    c.difference.push_back(d);
    sq += d * d;
    if (std::abs(d) > c.max_error) c.max_error = std::abs(d), c.max_error_x = c.x[i];
  }
  c.rms_error = std::sqrt(sq / c.x.size());
  std::tie(c.sim_peak, c.sim_peak_x) = peak(c.x, c.simulation);
  std::tie(c.mean_peak, c.mean_peak_x) = peak(c.x, c.mean);
  c.peak_error = (c.sim_peak - c.mean_peak) / c.mean_peak;
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
  j["range_mm"] = {1e3 * c.x.front(), 1e3 * c.x.back()};
  j["samples"] = c.x.size();
  j["simulation_peak_force_N"] = c.sim_peak;
  j["simulation_peak_displacement_mm"] = 1e3 * c.sim_peak_x;
  j["mean_peak_force_N"] = c.mean_peak;
  j["mean_peak_displacement_mm"] = 1e3 * c.mean_peak_x;
  j["peak_force_error_percent"] = 100 * c.peak_error;
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
  p.series.push_back({"simulation", x_mm, c.simulation});
  for (size_t k = 0; k < c.runs.size(); ++k) {
    p.series.push_back({fmt::format("measurement {}", k + 1), x_mm, c.runs[k]});
  }
  p.series.push_back({"measured mean", x_mm, c.mean});
  p.series.push_back({"difference (simulation - mean)", x_mm, c.difference});
  write_plot(dir + "/comparison.png", p);
}

}  // namespace finseg
