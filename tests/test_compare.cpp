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

#include <nlohmann/json.hpp>

#include "comparison/compare.hpp"
#include "core/error.hpp"
#include "test_paths.hpp"

namespace finseg {
namespace compare_test {

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
  expect_input_error("pull_displacement_mm\n0\n1\n2\n3\n", "no force column");
  expect_input_error("0,1\n1,2\n2,3\n3,4\n4,5\n", "header line");
  expect_input_error("pull_displacement_mm,force_N\n0,1\n1,1e308\n2,3\n3,4\n", "below 1e100");
  expect_input_error("pull_displacement_mm,force_N\n0,1\n1e308,1\n2,3\n3,4\n", "line 3");
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

TEST(Compare, SemicolonFilesWithDecimalCommasReadLikeCommaFiles) {
  // Former defect: a ';'-separated file was refused.
  const ForceCurve comma = read_force_curve(
      write("comma.csv", "pull_displacement_mm,force_N\n0,0.5\n1.5,1.25\n3,2\n4.5,2.5\n"));
  const ForceCurve semi = read_force_curve(
      write("semi.csv", "pull_displacement_mm;force_N\n0;0,5\n1,5;1,25\n3;2\n4,5;2,5\n"));
  EXPECT_EQ(semi.x, comma.x);
  EXPECT_EQ(semi.force, comma.force);
  EXPECT_NEAR(semi.x[1], 1.5e-3, 1e-15);
}

TEST(Compare, HeaderWithoutUnitsIsReadInMillimetresAndNewtonsWithANote) {
  // Former defect: headers without a unit suffix were refused. Documented defaults: the
  // first column is the displacement in mm, the next the force in N.
  const ForceCurve c =
      read_force_curve(write("nounit.csv", "position,weight\n0,1\n10,2\n20,3\n30,4\n"));
  EXPECT_NEAR(c.x[1], 0.010, 1e-15);
  EXPECT_NEAR(c.force[3], 4.0, 0);
  ASSERT_EQ(c.notes.size(), 2u);
  EXPECT_NE(c.notes[0].find("'position'"), std::string::npos) << c.notes[0];
  EXPECT_NE(c.notes[0].find("mm"), std::string::npos) << c.notes[0];
  EXPECT_NE(c.notes[1].find("in N"), std::string::npos) << c.notes[1];
  // Named columns without a suffix get the same defaults; a suffix still rules.
  const ForceCurve named = read_force_curve(
      write("named.csv", "t_s,pos,f_mN\n0,0,1\n1,10,2\n2,20,3\n3,30,4\n"), "pos", "f_mN");
  EXPECT_NEAR(named.x[2], 0.020, 1e-15);
  EXPECT_NEAR(named.force[2], 3e-3, 1e-15);
  EXPECT_EQ(named.notes.size(), 1u);
}

// A hump of 1 N at 30 mm then a taut rise to 2 N at 100 mm (sampled every mm).
std::string hump_and_rise(double scale) {
  std::string s = "pull_displacement_mm,force_N\n";
  for (int i = 0; i <= 100; ++i) {
    const double x = i;
    const double f = std::exp(-std::pow((x - 30) / 8, 2)) + 2 * std::pow(x / 100, 10);
    s += std::to_string(x) + "," + std::to_string(scale * f) + "\n";
  }
  return s;
}

TEST(Compare, PeakErrorUsesDeploymentPeaksNotTheTautEnd) {
  // Former defect: the peak error took the largest force over the whole travel, the end of
  // the taut rise. Simulation 10 % above the measurement: the deployment peaks differ by
  // 10 %, at 30 mm.
  const ForceCurve sim = read_force_curve(write("hs.csv", hump_and_rise(1.1)));
  const ForceCurve exp = read_force_curve(write("he.csv", hump_and_rise(1.0)));
  const Comparison c = compare_curves(sim, {exp}, 101);
  EXPECT_EQ(c.peak_rule, "deployment");
  EXPECT_NEAR(c.mean_peak_x, 0.030, 1e-12);
  EXPECT_NEAR(c.sim_peak_x, 0.030, 1e-12);
  EXPECT_NEAR(c.peak_error, 0.1, 2e-5);  // CSV values carry 6 decimals
  EXPECT_NEAR(c.mean_max_x, 0.100, 1e-12);
  EXPECT_NEAR(c.mean_max, 2.0 + std::exp(-std::pow(70 / 8.0, 2)), 1e-6);
  // --window 40,100 mm: no hump inside, the force only rises: the largest forces are used.
  const Comparison w = compare_curves(sim, {exp}, 61, {0.040, 0.100});
  EXPECT_NEAR(w.x.front(), 0.040, 1e-15);
  EXPECT_EQ(w.peak_rule, "largest");
  EXPECT_NEAR(w.mean_peak_x, 0.100, 1e-12);
  EXPECT_THROW(compare_curves(sim, {exp}, 61, {0.2, 0.3}), InputError);
}

TEST(Compare, JsonKeysAreTheDocumentedOnesAndPlotHasBandAndPeaks) {
  const std::string sim = write("js.csv", hump_and_rise(1.1));
  const std::string e1 = write("je1.csv", hump_and_rise(1.0));
  const std::string e2 = write("je2.csv", hump_and_rise(0.9));
  const fs::path out = temp_dir() / "jout";
  const std::string cmd = std::string(FINSEG_BINARY) + " compare " + sim + " " + e1 + " " + e2 +
                          " --window 0,90 --out " + out.string() + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  std::ifstream jin(out / "comparison.json");
  const nlohmann::json j = nlohmann::json::parse(jin);
  std::ifstream din(fs::path(FINSEG_SOURCE_DIR) / "docs/compare.md");
  const std::string doc((std::istreambuf_iterator<char>(din)), std::istreambuf_iterator<char>());
  // Former defect: comparison.json's keys differed from docs/compare.md.
  for (const auto& [key, value] : j.items()) {
    EXPECT_NE(doc.find("`" + key + "`"), std::string::npos) << key << " is not documented";
  }
  EXPECT_NEAR(j["range_mm"][1].get<double>(), 90, 1e-9);
  EXPECT_NEAR(j["peak_force_error_percent"].get<double>(), 100 * (1.1 - 0.95) / 0.95, 3e-3);
  std::ifstream gin(out / "comparison.png.gp");
  const std::string gp((std::istreambuf_iterator<char>(gin)), std::istreambuf_iterator<char>());
  EXPECT_NE(gp.find("filledcurves"), std::string::npos);
  EXPECT_NE(gp.find("simulation deployment peak"), std::string::npos);
  EXPECT_NE(gp.find("measured deployment peak"), std::string::npos);
}

TEST(Compare, HugeValuesExitWithStatus2) {
  // Former defect: 1e308 inputs gave NaN/inf results with exit status 0.
  const std::string sim =
      write("hs2.csv", curve_csv("pull_displacement_m,force_N", grid(0, 0.1, 11), 1, 1, f));
  const std::string big =
      write("big.csv", "pull_displacement_mm,force_N\n0,1e308\n1,1e308\n2,1e308\n3,1e308\n");
  const std::string cmd = std::string(FINSEG_BINARY) + " compare " + sim + " " + big +
                          " --no-plot --out " + (temp_dir() / "bigout").string() +
                          " > /dev/null 2>&1";
  const int rc = std::system(cmd.c_str());
  EXPECT_TRUE(WIFEXITED(rc) && WEXITSTATUS(rc) == 2) << rc;
}

}  // namespace compare_test
}  // namespace finseg
