#include "fitting/fit_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "writers/atomic_write.hpp"
#include "writers/plot.hpp"

namespace finseg {
namespace {

// JSON number, or null for NaN (not defined).
nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

std::string fit_csv(const FitSpec& spec, const FitResult& r) {
  std::string csv =
      "curve,pull_displacement_mm,measured_mean_N,measured_stddev_N,initial_N,fitted_N,"
      "residual_N\n";
  for (std::size_t k = 0; k < spec.curves.size(); ++k) {
    const auto& x = spec.curves[k].x;
    const MeasuredSpread& m = r.measured[k];
    for (std::size_t i = 0; i < x.size(); ++i) {
      csv += fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", k + 1, 1e3 * x[i],
                         m.mean[i], m.stddev[i], r.initial_curves[k][i], r.fitted_curves[k][i],
                         r.fitted_curves[k][i] - m.mean[i]);
    }
  }
  return csv;
}

nlohmann::json fit_json(const FitSpec& spec, const FitResult& r, double wall_s) {
  const std::size_t n = spec.parameters.size();
  nlohmann::json j;
  j["fit_file"] = spec.file;
  j["termination"] = r.termination;
  j["message"] = r.message;
  for (std::size_t i = 0; i < n; ++i) {
    const FitParameter& p = spec.parameters[i];
    const nlohmann::json path =
        p.paths.size() == 1 ? nlohmann::json(p.path) : nlohmann::json(p.paths);
    j["parameters"].push_back({{"path", path},
                               {"initial", p.initial},
                               {"value", r.values[i]},
                               {"standard_error", number_or_null(r.standard_errors[i])},
                               {"lower", number_or_null(p.lower)},
                               {"upper", number_or_null(p.upper)},
                               {"scale", p.scale},
                               {"at_bound", static_cast<bool>(r.at_bound[i])}});
  }
  nlohmann::json corr = nlohmann::json::array();
  for (std::size_t i = 0; i < n; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (std::size_t k = 0; k < n; ++k) row.push_back(number_or_null(r.correlation(i, k)));
    corr.push_back(row);
  }
  j["correlation"] = corr;
  for (std::size_t k = 0; k < spec.curves.size(); ++k) {
    const FitCurve& c = spec.curves[k];
    nlohmann::json files = nlohmann::json::array();
    for (const ForceCurve& m : c.runs) files.push_back(m.source);
    double sq = 0;
    for (std::size_t i = 0; i < c.x.size(); ++i) {
      sq += std::pow(r.fitted_curves[k][i] - r.measured[k].mean[i], 2);
    }
    j["curves"].push_back({{"scene", c.scene},
                           {"measurements", files},
                           {"points", c.x.size()},
                           {"range_mm", {1e3 * c.x.front(), 1e3 * c.x.back()}},
                           {"rms_N", std::sqrt(sq / c.x.size())}});
  }
  j["residuals"] = r.residuals;
  j["degrees_of_freedom"] = r.residuals - n;
  j["rss_N2"] = r.rss;
  j["sigma_N"] = std::sqrt(r.rss / static_cast<double>(r.residuals - n));
  j["initial_rms_N"] = r.initial_rms;
  j["final_rms_N"] = r.final_rms;
  j["iterations"] = r.iterations;
  j["simulations"] = r.simulations;
  j["relative_step"] = spec.solver.relative_step;
  j["wall_time_s"] = wall_s;
  return j;
}

PlotSpec fit_plot(const FitSpec& spec, const FitResult& r) {
  PlotSpec p;
  p.title = fmt::format("Fit of {} parameter(s): rms {:.4g} N -> {:.4g} N", spec.parameters.size(),
                        r.initial_rms, r.final_rms);
  p.x_label = "pull displacement (mm)";
  p.y_label = "force (N)";
  const bool several = spec.curves.size() > 1;
  for (std::size_t k = 0; k < spec.curves.size(); ++k) {
    const std::string tag = several ? fmt::format(" (curve {})", k + 1) : "";
    std::vector<double> x_mm;
    for (double x : spec.curves[k].x) x_mm.push_back(1e3 * x);
    const MeasuredSpread& m = r.measured[k];
    p.bands.push_back({"measured spread (min - max)" + tag, x_mm, m.min, m.max});
    p.series.push_back({"measured mean" + tag, x_mm, m.mean});
    p.series.push_back({"initial simulation" + tag, x_mm, r.initial_curves[k]});
    p.series.push_back({"fitted simulation" + tag, x_mm, r.fitted_curves[k]});
  }
  if (r.termination != "convergence") p.warning = "FIT DID NOT CONVERGE: " + r.message;
  return p;
}

}  // namespace

void write_fit(const FitSpec& spec, const FitResult& r, const std::string& dir, double wall_s) {
  std::filesystem::create_directories(dir);
  write_file_atomically(dir + "/fit.csv", fit_csv(spec, r));
  write_file_atomically(dir + "/fit.json", fit_json(spec, r, wall_s).dump(2) + "\n");
}

void write_fit_plot(const FitSpec& spec, const FitResult& r, const std::string& dir) {
  write_plot(dir + "/fit.png", fit_plot(spec, r));
}

}  // namespace finseg
