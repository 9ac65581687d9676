// finseg gen -> run -> summary.json / CSV, inspect and modes against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "cli_test_util.hpp"
#include "core/types.hpp"

namespace finseg {
namespace cli_run_test {

using test::csv_rows;
using test::run_finseg;
using test::slurp;
using test::TempDir;

// Linear beam theory with shear: w = P L^3 / (3 E I) + P L / (kappa G A).
TEST(CliRun, CantileverTipMatchesLinearBeamTheory) {
  TempDir dir;
  const double L = 0.1, b = 0.02, t = 1e-3, E = 2e9, nu = 0.3, P = 2e-3;
  auto r = run_finseg(dir,
                      "gen cantilever --length 0.1 --width 0.02 --thickness 1e-3 "
                      "--modulus 2e9 --poisson 0.3 --segments 16 --tip-force 0,0,-2e-3 "
                      "--out c.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "run c.yaml --out out");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(dir / "out/summary.json"));
  EXPECT_EQ(j["status"], "ok");
  const std::vector<double> tip = j["probes"]["tip"]["final"];
  ASSERT_EQ(tip.size(), 3u);
  const double I = b * t * t * t / 12, G = E / (2 * (1 + nu)), A = b * t;
  const double w = P * L * L * L / (3 * E * I) + P * L / (5.0 / 6.0 * G * A);
  ASSERT_GT(w, 1e-4 * L);  // measurable, still small (w / L = 2e-3: linear regime)
  ASSERT_LT(w, 5e-3 * L);
  EXPECT_NEAR(-tip[2] / w, 1.0, 0.01);
  EXPECT_NEAR(tip[1], 0.5 * b, 1e-12);
  std::string header;
  const auto rows = csv_rows(slurp(dir / "out/tip.csv"), &header);
  EXPECT_EQ(header, "load_scale,x_m,y_m,z_m");
  ASSERT_GE(rows.size(), 2u);
  EXPECT_NEAR(rows.back()[3], tip[2], 1e-11 * std::abs(tip[2]));      // CSV: 12 digits
  EXPECT_FALSE(std::filesystem::exists(dir / "out/animation.html"));  // off for cantilevers
}

// --threads sets the element loop's threads and summary.json says how many; out of range
// is refused naming the option.
TEST(CliRun, ThreadsOptionIsRecordedAndRangeChecked) {
  TempDir dir;
  auto r = run_finseg(dir, "gen cantilever --segments 8 --tip-force 0,0,-1e-3 --out c.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "run c.yaml --out out --threads 1 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(slurp(dir / "out/summary.json"))["threads"], 1);
  r = run_finseg(dir, "run c.yaml --out out2 --threads -2 --quiet");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
}

// First bending frequency of a clamped-free beam: beta_1 L = 1.87510407,
// f = (beta_1 L)^2 / (2 pi L^2) sqrt(E I / (rho A)).
TEST(CliModes, CantileverFirstFrequency) {
  TempDir dir;
  auto r = run_finseg(dir, "gen cantilever --segments 24 --out c.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "modes c.yaml --count 2 --out modes.csv");
  ASSERT_EQ(r.code, 0) << r.err;
  std::string header;
  const auto rows = csv_rows(slurp(dir / "modes.csv"), &header);
  EXPECT_EQ(header, "mode,frequency_Hz");
  ASSERT_EQ(rows.size(), 2u);
  const double L = 0.1, b = 0.02, t = 1e-4, E = 4e9, rho = 800;  // gen cantilever defaults
  const double bl = 1.87510407;
  const double f1 = bl * bl / (2 * kPi * L * L) * std::sqrt(E * b * t * t * t / 12 / (rho * b * t));
  EXPECT_NEAR(rows[0][1] / f1, 1.0, 0.01);
}

// Paper eqs. 1-4 for a chain of 3 cells (half cells at clamp and tip): element k joins
// body k (outer, S = -1) and body k+1 (inner, S = +1) at s = (k + 1/2) h.
TEST(CliInspect, IncidenceAndLeversOfAChain) {
  TempDir dir;
  auto r = run_finseg(dir, "gen cantilever --segments 3 --length 0.3 --out c.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "inspect c.yaml --incidence S.csv --levers c.csv");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("bodies 4 (1 fixed), elements 3"), std::string::npos) << r.out;
  EXPECT_EQ(slurp(dir / "S.csv"),
            "body,joint_r0_s0,joint_r0_s1,joint_r0_s2\n"
            "seg_r0_s0,-1,0,0\n"
            "seg_r0_s1,1,-1,0\n"
            "seg_r0_s2,0,1,-1\n"
            "seg_r0_s3,0,0,1\n");
  std::string header;
  const auto text = slurp(dir / "c.csv");
  std::stringstream in(text);
  std::getline(in, header);
  EXPECT_EQ(header, "element,element_name,body,body_name,S,c_x_m,c_y_m,c_z_m");
  const double h = 0.1;
  const double body_length[4] = {h / 2, h, h, h / 2};
  std::string line;
  for (int k = 0; k < 3; ++k) {
    for (int side = 0; side < 2; ++side) {
      ASSERT_TRUE(std::getline(in, line));
      std::vector<std::string> f;
      std::stringstream cells(line);
      std::string cell;
      while (std::getline(cells, cell, ',')) f.push_back(cell);
      ASSERT_EQ(f.size(), 8u);
      const int body = side == 0 ? k + 1 : k, S = side == 0 ? 1 : -1;
      EXPECT_EQ(std::stoi(f[2]), body);
      EXPECT_EQ(std::stoi(f[4]), S);
      // Inner body: the joint is at its start (-half length); outer: at its end (+half).
      EXPECT_NEAR(std::stod(f[5]), -S * body_length[body] / 2, 1e-15);
      EXPECT_EQ(std::stod(f[6]), 0.0);
      EXPECT_EQ(std::stod(f[7]), 0.0);
    }
  }
}

// Quasi-static pull of a small zigzag: the drive CSV, the peak in summary.json, phases and
// the animation outputs are there and consistent.
TEST(CliRun, ZigzagPullWritesDriveCurveAndAnimation) {
  TempDir dir;
  auto r = run_finseg(dir,
                      "gen zigzag --segments-per-panel 3 --pull-travel 0.03 --pull-step 0.005 "
                      "--no-contact --out z.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "run z.yaml --out out");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(dir / "out/summary.json"));
  EXPECT_EQ(j["status"], "ok");
  std::string header;
  const auto rows = csv_rows(slurp(dir / "out/gauge.csv"), &header);
  EXPECT_EQ(header.rfind("pull_displacement_m,force_N,", 0), 0u) << header;
  ASSERT_EQ(rows.size(), 7u);  // start + 6 steps of 5 mm
  EXPECT_NEAR(rows.back()[0], 0.03, 1e-12);
  double peak = -INFINITY, at = 0;
  for (const auto& row : rows) {
    if (row[1] > peak) peak = row[1], at = row[0];
  }
  EXPECT_NEAR(j["probes"]["gauge"]["peak_force_N"].get<double>(), peak, 1e-9 * std::abs(peak));
  EXPECT_NEAR(j["probes"]["gauge"]["peak_displacement_m"].get<double>(), at, 1e-12);
  EXPECT_TRUE(j.contains("phases"));
  EXPECT_EQ(j["phases"]["watched_panels"], nlohmann::json({2, 5}));
  for (const char* f : {"reaction.csv", "energy.csv", "phases.csv", "vtk/frames.pvd"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / (std::string("out/") + f))) << f;
  }
  // The page's slider and chart both say mm and their numbers are mm (the slider said [m]).
  const std::string page = slurp(dir / "out/animation.html");
  EXPECT_NE(page.find(R"("timeLabel":"pull displacement [mm]")"), std::string::npos);
  EXPECT_NE(page.find(R"("frames":{"t":[0,5,10,15,20,25,30])"), std::string::npos);
  EXPECT_NE(page.find(R"("xLabel":"pull displacement [mm]")"), std::string::npos);
}

// A far too large explicit step: exit 3, status "diverged", the rows before the blow-up kept.
TEST(CliRun, DivergingRunKeepsWhatItRecorded) {
  TempDir dir;
  auto r = run_finseg(dir,
                      "gen cantilever --segments 8 --tip-force 0,0,-1e-3 --solver explicit "
                      "--t-end 0.2 --dt 2e-3 --output-interval 2e-3 --out c.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "run c.yaml --out out");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("diverged"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(slurp(dir / "out/summary.json"));
  EXPECT_EQ(j["status"], "diverged");
  EXPECT_FALSE(j["message"].get<std::string>().empty());
  std::string header;
  const auto rows = csv_rows(slurp(dir / "out/tip.csv"), &header);
  EXPECT_EQ(header, "t_s,x_m,y_m,z_m");
  ASSERT_GE(rows.size(), 2u);    // t = 0 and at least one step
  EXPECT_LT(rows.size(), 101u);  // stopped before t_end
  EXPECT_EQ(j["outputs"].get<std::size_t>(), rows.size());
  for (const auto& row : rows) {
    for (double v : row) EXPECT_TRUE(std::isfinite(v));
  }
}

}  // namespace cli_run_test
}  // namespace finseg
