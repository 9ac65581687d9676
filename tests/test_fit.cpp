// finseg fit (issue 15 item 3): parameters recovered from synthetic measurements made by
// running a small zigzag pull with known parameters: within 1 % without noise, within three
// reported standard errors with Gaussian noise of a fixed seed; bad fit files refused.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_test_util.hpp"
#include "core/error.hpp"
#include "fitting/fit_solve.hpp"
#include "fitting/fit_spec.hpp"

namespace finseg {
namespace fit_test {

using test::csv_rows;
using test::run_finseg;
using test::slurp;
using test::spit;
using test::TempDir;

// The true parameters of the synthetic measurements: a linear crease stiffness (N m/rad) and
// the sheet's density (kg/m^3: its weight, which the pull lifts). Crease stiffness and bending
// rigidity would be a poor pair here: they change this curve almost alike (correlation
// -0.99993), so one curve does not separate them.
constexpr double kCrease = 2.7e-3, kDensity = 800, kBending = 4e-4;

// A small strip (the paper's 6 panels, 2 segments each, no contact) pulled 20 mm in 1 mm
// steps: a fraction of a second per run. Writes z.yaml in `dir`.
void write_scene(const TempDir& dir) {
  const auto r = run_finseg(
      dir, fmt::format(
               "gen zigzag --segments-per-panel 2 --no-contact --pull-step 1e-3 --pull-travel 0.02 "
               "--crease-stiffness {} --bending-rigidity {} --out z.yaml",
               kCrease, kBending));
  ASSERT_EQ(r.code, 0) << r.err;
}

// The true run's gauge curve: pull_displacement_m and force_N columns.
std::vector<std::vector<double>> true_curve(const TempDir& dir) {
  const auto r = run_finseg(dir,
                            "run z.yaml --out truth --quiet "
                            "--set 'outputs={vtk: false, html: false, plot: false}'");
  EXPECT_EQ(r.code, 0) << r.err;
  std::string header;
  auto rows = csv_rows(slurp(dir / "truth/gauge.csv"), &header);
  EXPECT_EQ(header.rfind("pull_displacement_m,force_N,", 0), 0u) << header;
  return rows;
}

// A measurement file: the true curve plus Gaussian noise of `sigma` N.
void write_measurement(const std::string& path, const std::vector<std::vector<double>>& truth,
                       double sigma, std::mt19937& rng) {
  std::normal_distribution<double> noise(0, sigma);
  std::string csv = "pull_displacement_m,force_N\n";
  for (const auto& row : truth) {
    csv += fmt::format("{:.17g},{:.17g}\n", row[0], row[1] + (sigma > 0 ? noise(rng) : 0.0));
  }
  spit(path, csv);
}

std::string fit_file(const std::string& measurements) {
  return "scene: z.yaml\n"
         "curves:\n"
         "  - measurements: " +
         measurements +
         "\n"
         "parameters:\n"
         "  - path: [zigzag.crease_laws.0.stiffness, zigzag.crease_laws.1.stiffness,\n"
         "           zigzag.crease_laws.2.stiffness, zigzag.crease_laws.3.stiffness,\n"
         "           zigzag.crease_laws.4.stiffness]  # one stiffness for every crease\n"
         "    initial: 4e-3\n"
         "    lower: 1e-4\n"
         "    upper: 1e-2\n"
         "  - {path: material.density, initial: 500, lower: 10, upper: 1e4}\n";
}

// Without noise the known parameters come back within 1 % (the command line end to end).
TEST(Fit, RecoversKnownParametersWithoutNoise) {
  const TempDir dir;
  write_scene(dir);
  std::mt19937 rng(1);
  write_measurement(dir / "m1.csv", true_curve(dir), 0, rng);
  spit(dir / "fit.yaml", fit_file("[m1.csv]"));
  const auto r = run_finseg(dir, "fit fit.yaml --out out");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(slurp(dir / "out/fit.json"));
  EXPECT_EQ(j["termination"], "convergence");
  EXPECT_NEAR(j["parameters"][0]["value"].get<double>(), kCrease, 0.01 * kCrease) << j.dump(1);
  EXPECT_NEAR(j["parameters"][1]["value"].get<double>(), kDensity, 0.01 * kDensity) << j.dump(1);
  EXPECT_LT(j["final_rms_N"].get<double>(), 1e-3 * j["initial_rms_N"].get<double>());
  EXPECT_GT(j["simulations"].get<int>(), 2 * 2 + 1);  // at least one central-difference Jacobian
  std::string header;
  const auto rows = csv_rows(slurp(dir / "out/fit.csv"), &header);
  EXPECT_EQ(header,
            "curve,pull_displacement_mm,measured_mean_N,measured_stddev_N,initial_N,fitted_N,"
            "residual_N");
  EXPECT_EQ(rows.size(), 21u);
  EXPECT_TRUE(std::filesystem::exists(dir / "out/fit.png"));
}

// With noise (two repeated measurements, fixed seed) each parameter lies within three of its
// reported standard errors of the truth, and the residual scatter sigma matches the noise of
// the mean of two measurements, noise / sqrt(2).
TEST(Fit, RecoversParametersWithinTheirStandardErrorsWithNoise) {
  const TempDir dir;
  write_scene(dir);
  const auto truth = true_curve(dir);
  double peak = 0;
  for (const auto& row : truth) peak = std::max(peak, std::abs(row[1]));
  const double noise = 0.02 * peak;
  std::mt19937 rng(20240615);
  write_measurement(dir / "m1.csv", truth, noise, rng);
  write_measurement(dir / "m2.csv", truth, noise, rng);
  spit(dir / "fit.yaml", fit_file("[m1.csv, m2.csv]"));
  const FitSpec spec = read_fit(dir / "fit.yaml");
  const FitResult r = run_fit(spec);
  ASSERT_EQ(r.termination, "convergence") << r.message;
  const double truths[] = {kCrease, kDensity};
  for (int i = 0; i < 2; ++i) {
    ASSERT_TRUE(std::isfinite(r.standard_errors[i]) && r.standard_errors[i] > 0);
    EXPECT_LT(std::abs(r.values[i] - truths[i]), 3 * r.standard_errors[i])
        << spec.parameters[i].path << " = " << r.values[i] << " +- " << r.standard_errors[i];
  }
  const double sigma = std::sqrt(r.rss / (r.residuals - 2));
  EXPECT_GT(sigma, 0.5 * noise / std::sqrt(2.0));
  EXPECT_LT(sigma, 1.5 * noise / std::sqrt(2.0));
  EXPECT_NEAR(r.correlation(0, 1), r.correlation(1, 0), 1e-12);
  EXPECT_LT(std::abs(r.correlation(0, 1)), 1.0);
}

TEST(Fit, BadFitFilesNameTheField) {
  const TempDir dir;
  spit(dir / "z.yaml", "title: x\n");
  spit(dir / "m.csv", "pull_displacement_mm,force_N\n0,0\n1,1\n2,2\n3,3\n");
  const auto field_of = [&](const std::string& yaml) {
    spit(dir / "f.yaml", yaml);
    try {
      read_fit(dir / "f.yaml");
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string("accepted");
  };
  const std::string curves = "curves: [{measurements: [m.csv]}]\n";
  const std::string p = "parameters: [{path: a.b, initial: 1}]\n";
  EXPECT_EQ(field_of("scene: z.yaml\n" + curves + p), "accepted");
  EXPECT_EQ(field_of(curves + p), "curves[0].scene");
  EXPECT_EQ(field_of("scene: nothere.yaml\n" + curves + p), "curves[0].scene");
  EXPECT_EQ(field_of("scene: z.yaml\n" + p), "curves");
  EXPECT_EQ(field_of("scene: z.yaml\n" + curves), "parameters");
  EXPECT_EQ(field_of("scene: z.yaml\n" + curves +
                     "parameters: [{path: a, initial: 5, lower: 0, upper: 1}]\n"),
            "parameters[0].initial");
  EXPECT_EQ(field_of("scene: z.yaml\n" + curves +
                     "parameters: [{path: a, initial: 0.5, lower: 1, upper: 0}]\n"),
            "parameters[0].upper");
  EXPECT_EQ(field_of("scene: z.yaml\n" + curves + "parameters: [{path: a, initial: 0}]\n"),
            "parameters[0].scale");
  EXPECT_EQ(field_of("scene: z.yaml\n" + curves + "parameters: [{path: a..b, initial: 1}]\n"),
            "parameters[0].path");
  EXPECT_EQ(
      field_of("scene: z.yaml\n" + curves +
               "parameters:\n  - {path: a.b, initial: 1}\n  - {path: [c, a.b], initial: 2}\n"),
      "parameters[1].path");
  EXPECT_EQ(field_of("scene: z.yaml\ncurves: [{measurements: [m.csv], window_mm: [5, 9]}]\n" + p),
            "curves[0].window_mm");
  EXPECT_EQ(field_of("scene: z.yaml\ncurves: [{measurements: [m.csv], samples: 1}]\n" + p),
            "curves[0].samples");
  EXPECT_EQ(field_of("scene: z.yaml\ncurves: [{measurements: [m.csv], set: [nothing]}]\n" + p),
            "curves[0].set");
  EXPECT_EQ(field_of("scene: z.yaml\n" + curves + p + "solver: {relative_step: 1}\n"),
            "solver.relative_step");
  EXPECT_EQ(field_of("scene: z.yaml\n" + curves + p + "extra: 1\n"), "extra");
  // 4 measured points and 4 parameters: no degrees of freedom left for the standard errors.
  EXPECT_EQ(field_of("scene: z.yaml\n" + curves +
                     "parameters:\n  - {path: a, initial: 1}\n  - {path: b, initial: 1}\n"
                     "  - {path: c, initial: 1}\n  - {path: d, initial: 1}\n"),
            "curves");
}

}  // namespace fit_test
}  // namespace finseg
