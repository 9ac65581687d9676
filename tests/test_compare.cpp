// finseg compare: curves whose mean, spread and errors are known in closed form, and bad
// experiment files.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "comparison/compare.hpp"
#include "core/error.hpp"

namespace finseg {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("finseg_compare_" + std::to_string(getpid()));
  fs::create_directories(d);
  return d;
}

std::string write(const std::string& name, const std::string& text) {
  const fs::path p = temp_dir() / name;
  std::ofstream(p) << text;
  return p.string();
}

// A parabola with its maximum 1 N at 50 mm; splines reproduce it exactly.
double f(double x) {
  return 1 - 100 * (x - 0.05) * (x - 0.05);
}

std::string curve_csv(const std::string& header, const std::vector<double>& x_m, double x_scale,
                      double y_scale, const std::function<double(double)>& y) {
  std::string s = "# synthetic curve\n" + header + "\n";
  for (double x : x_m)
    s += std::to_string(x * x_scale) + "," + std::to_string(y(x) * y_scale) + "\n";
  return s;
}

std::vector<double> grid(double a, double b, int n) {
  std::vector<double> x;
  for (int i = 0; i < n; ++i) x.push_back(a + (b - a) * i / (n - 1));
  return x;
}

TEST(Compare, MeanSpreadAndErrorsOfAnalyticCurves) {
  // Simulation in m and N over [0, 120] mm; three measurements in mm (one in mN) over
  // different ranges at uneven points; offsets -0.1, 0, +0.1 N: mean f, sample sd 0.1 N.
  const double slope = 0.2;  // N/m: simulation = f + slope (x - 0.05)
  const ForceCurve sim = read_force_curve(
      write("sim.csv", curve_csv("pull_displacement_m,force_N", grid(0, 0.12, 13), 1, 1,
                                 [&](double x) { return f(x) + slope * (x - 0.05); })));
  std::vector<ForceCurve> runs;
  runs.push_back(read_force_curve(
      write("e1.csv", curve_csv("pull_displacement_mm,force_mN", {0, 0.013, 0.04, 0.07, 0.1}, 1e3,
                                1e3, [](double x) { return f(x) - 0.1; }))));
  runs.push_back(read_force_curve(
      write("e2.csv", curve_csv("pull_displacement_mm,force_N", grid(-0.01, 0.11, 7), 1e3, 1,
                                [](double x) { return f(x); }))));
  runs.push_back(read_force_curve(
      write("e3.csv", curve_csv("pull_displacement_mm,force_N", {0, 0.03, 0.05, 0.08, 0.105}, 1e3,
                                1, [](double x) { return f(x) + 0.1; }))));
  const Comparison c = compare_curves(sim, runs, 201);
  ASSERT_EQ(c.x.size(), 201u);
  EXPECT_NEAR(c.x.front(), 0.0, 1e-12);  // common range [0, 100] mm
  EXPECT_NEAR(c.x.back(), 0.1, 1e-12);
  double sq = 0;
  for (size_t i = 0; i < c.x.size(); ++i) {
    const double x = c.x[i];
    EXPECT_NEAR(c.mean[i], f(x), 1e-5) << x;
    EXPECT_NEAR(c.stddev[i], 0.1, 1e-5) << x;
    EXPECT_NEAR(c.min[i], f(x) - 0.1, 1e-5) << x;
    EXPECT_NEAR(c.max[i], f(x) + 0.1, 1e-5) << x;
    EXPECT_NEAR(c.difference[i], slope * (x - 0.05), 1e-5) << x;
    sq += std::pow(slope * (x - 0.05), 2);
  }
  EXPECT_NEAR(c.rms_error, std::sqrt(sq / 201), 1e-5);
  EXPECT_NEAR(c.max_error, slope * 0.05, 1e-5);
  // Peaks: mean 1 N at 50 mm; simulation 1 + slope^2/400 N at 0.05 + slope/200 m = 51 mm.
  EXPECT_NEAR(c.mean_peak, 1.0, 1e-5);
  EXPECT_NEAR(c.mean_peak_x, 0.05, 1e-9);
  EXPECT_NEAR(c.sim_peak_x, 0.051, 1e-9);
  EXPECT_NEAR(c.sim_peak, 1 + slope * slope / 400, 1e-6);
  EXPECT_NEAR(c.peak_error, slope * slope / 400, 1e-5);
}

void expect_input_error(const std::string& text, const std::string& needle) {
  const std::string path = write("bad.csv", text);
  try {
    read_force_curve(path);
    FAIL() << "no error for: " << text;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find(needle), std::string::npos) << what;
  }
}

TEST(Compare, BadExperimentFilesNameFileAndLine) {
  expect_input_error("pull_displacement_mm,weight\n0,1\n1,2\n2,3\n3,4\n", "force");
  expect_input_error("position,force_N\n0,1\n1,2\n2,3\n3,4\n", "displacement");
  expect_input_error("pull_displacement_mm,force_N\n0,1\n2,2\n1,3\n3,4\n", "line 4");
  expect_input_error("pull_displacement_mm,force_N\n0,1\n1,1\n1,3\n3,4\n", "increase");
  expect_input_error("pull_displacement_mm,force_N\n0,1\n1,2\n2,3\n", "at least 4");
  expect_input_error("# c\npull_displacement_mm,force_N\n0,1\n1,nan\n2,3\n3,4\n", "line 4");
  expect_input_error("pull_displacement_mm,force_N\n0,1\n1,abc\n2,3\n3,4\n", "not a number");
  expect_input_error("pull_displacement_mm,force_N\n0,1\n1\n2,3\n3,4\n", "line 3");
}

TEST(Compare, CommandLineExitsNonZeroOnBadInput) {
  const std::string sim =
      write("s.csv", curve_csv("pull_displacement_m,force_N", grid(0, 0.1, 11), 1, 1, f));
  const std::string good =
      write("g.csv", curve_csv("pull_displacement_mm,force_N", grid(0, 0.1, 11), 1e3, 1, f));
  const std::string bad = write("b.csv", "pull_displacement_mm,force_N\n0,1\n2,2\n1,3\n3,4\n");
  const std::string out = (temp_dir() / "out").string();
  const std::string cmd = std::string(FINSEG_BINARY) + " compare " + sim + " " + good +
                          " --no-plot --out " + out + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_TRUE(fs::exists(out + "/comparison.csv"));
  EXPECT_TRUE(fs::exists(out + "/comparison.json"));
  const std::string bad_cmd = std::string(FINSEG_BINARY) + " compare " + sim + " " + bad +
                              " --no-plot --out " + out + " > /dev/null 2>&1";
  const int rc = std::system(bad_cmd.c_str());
  EXPECT_TRUE(WIFEXITED(rc) && WEXITSTATUS(rc) == 2) << rc;
}

}  // namespace
}  // namespace finseg
