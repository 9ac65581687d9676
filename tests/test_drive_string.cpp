// A drive whose gauge pulls only along its direction (`lateral_stiffness: 0`, docs/scene.md): a
// string from far away. A clamped strip with a small dead tip load P across it is pulled at its
// tip along its axis; the string's tension T, horizontal, stiffens the strip in bending, and the
// tip deflection follows the classical beam under axial tension (Timoshenko & Gere, Theory of
// Elastic Stability, beam-columns):
//   EI w'''' - T w'' = 0, w(0) = w'(0) = 0, EI w''(L) = 0, EI w'''(L) - T w'(L) = -P
//   => w(L) = (P / T) (L - tanh(lambda L) / lambda), lambda = sqrt(T / EI).
// The default, isotropic gauge also holds the tip sideways, a spring k in parallel with the
// tensioned strip: w(L) = P / (k + P / w_string(L)). A pull-only gauge goes slack where the
// point runs ahead of its target (a plate coasting at its own speed).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cli_test_util.hpp"
#include "contact_test_util.hpp"
#include "elements/drive_gauge.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace drive_string_test {

using test::csv_rows;
using test::run_finseg;
using test::slurp;
using test::spit;
using test::TempDir;

constexpr double kE = 4e9, kL = 0.1, kW = 0.02, kT = 1e-4, kP = 1e-5;  // SI
const double kEI = kE * kW * kT * kT * kT / 12;

std::string strip(int segments, const std::string& lateral) {
  return "material: {youngs_modulus: 4e9, poisson_ratio: 0, density: 800}\n"
         "sheet: {length: 0.1, width: 0.02, thickness: 1e-4}\n"
         "discretisation: {segments: " +
         std::to_string(segments) +
         "}\n"
         "fixtures: {clamp_start: true}\n"
         "loads: [{at: {s: 0.1, y: 0.01}, force: [0, 0, 1e-5]}]\n"
         "drives:\n"
         "  - {name: string, at: {s: 0.1, y: 0.01}, direction: [1, 0, 0], stiffness: 1,\n"
         "     travel: 0.009, step: 0.0015" +
         lateral +
         "}\n"
         "solver: {type: static, tolerance: 1e-12}\n"
         "outputs: {vtk: false, html: false, plot: false}\n"
         "probes:\n"
         "  - {name: pull, type: drive, drive: string}\n"
         "  - {name: tip, type: point, at: {s: 0.1, y: 0.01}}\n";
}

double beam_column_deflection(double tension) {
  const double lambda = std::sqrt(tension / kEI);
  return kP / tension * (kL - std::tanh(lambda * kL) / lambda);
}

struct Point {
  double tension, deflection;
};

// The pull's equilibria: the string's tension (the gauge force) and the tip's deflection.
std::vector<Point> pulled(int segments, const std::string& lateral) {
  TempDir dir;
  spit(dir / "s.yaml", strip(segments, lateral));
  const auto r = run_finseg(dir, "run s.yaml --out out --quiet");
  EXPECT_EQ(r.code, 0) << r.err;
  std::string header;
  const auto pull = csv_rows(slurp(dir / "out/pull.csv"), &header);
  const auto tip = csv_rows(slurp(dir / "out/tip.csv"), &header);
  EXPECT_EQ(pull.size(), tip.size());
  std::vector<Point> out;
  // pull: pull_displacement_m, force_N, ...; tip: pull_displacement_m, x_m, y_m, z_m
  for (std::size_t i = 0; i < pull.size() && i < tip.size(); ++i) {
    if (pull[i][0] > 0) out.push_back({pull[i][1], tip[i][3]});
  }
  return out;
}

TEST(DriveString, TensionStiffensTheTippedStripAsTheBeamColumn) {
  std::vector<double> worst;
  for (const int n : {16, 32}) {
    const auto points = pulled(n, ", lateral_stiffness: 0");
    ASSERT_EQ(points.size(), 6u);  // 1.5 mm steps to 9 mm
    double w = 0;
    for (const Point& p : points) {
      const double ref = beam_column_deflection(p.tension);
      w = std::max(w, std::abs(p.deflection / ref - 1));
      EXPECT_NEAR(p.deflection / ref, 1.0, 1e-2) << n << " segments, T " << p.tension << " N";
    }
    // lambda L from about 1.5 to 3.7: the tension matters.
    EXPECT_GT(points.back().tension, 12 * kEI / (kL * kL));
    EXPECT_LT(points.front().tension, 3 * kEI / (kL * kL));
    worst.push_back(w);
  }
  EXPECT_LT(worst[1], 0.5 * worst[0]) << "the error shrinks under refinement";
  std::printf("string pull: worst |w/w_ref - 1| %.3g (16 segments), %.3g (32)\n", worst[0],
              worst[1]);
}

TEST(DriveString, TheIsotropicGaugeHoldsTheTipSideways) {
  const auto points = pulled(32, "");
  ASSERT_EQ(points.size(), 6u);
  const double k = 1;  // N/m, the gauge's stiffness, now across the strip too
  for (const Point& p : points) {
    const double ref = kP / (k + kP / beam_column_deflection(p.tension));
    EXPECT_NEAR(p.deflection / ref, 1.0, 1e-2) << "T " << p.tension;
    EXPECT_LT(p.deflection, 0.2 * beam_column_deflection(p.tension)) << "T " << p.tension;
  }
}

// `pull_only: true` (a string): a free 1 g plate thrown along the drive at three times the
// target's speed runs ahead of it, where a string goes slack: no force, so the plate coasts,
// x = v0 t to round-off. The two-way gauge holds it back instead (about the target, within
// the amplitude (v0 - V) / omega of its oscillation, omega = sqrt(k / m)).
struct Thrown {
  double x = 0, largest_force = 0;
};

Thrown thrown_ahead(bool pull_only) {
  Model m;
  m.gravity_W = Vec3::Zero();
  m.bodies.push_back(test::plate("plate", 1e-3, Vec3(0.02, 0.02, 1e-4), Vec3::Zero()));
  DriveDef d;
  d.name = "string";
  d.body = 0;
  d.direction_W = Vec3::UnitX();
  d.stiffness = 10;
  d.lateral_ratio = 0;
  d.pull_only = pull_only;
  d.speed = 0.01;
  d.travel = 1;
  d.step = 0.01;
  m.drives.push_back(d);
  m.finalize_dofs();
  State s = initial_state(m);
  s.v_W[0] = Vec3(0.03, 0, 0);
  SolverSettings set;
  set.kind = SolverKind::Implicit;
  set.t_end = 0.5;
  set.output_interval = 0.01;
  Thrown r;
  const SolverStats stats = run_solver(m, s, set, [&](const State& at, const BodyForces&) {
    r.largest_force = std::max(r.largest_force, drive_force(m, at, 0).norm());
  });
  EXPECT_EQ(stats.status, "ok") << stats.message;
  r.x = s.p_W[0].x();
  return r;
}

TEST(DriveString, APullOnlyGaugeGoesSlackWhereThePointRunsAhead) {
  const Thrown slack = thrown_ahead(true), held = thrown_ahead(false);
  EXPECT_NEAR(slack.x, 0.03 * 0.5, 1e-12);
  EXPECT_EQ(slack.largest_force, 0);
  // Held at the target's 5 mm, within the oscillation's amplitude (v0 - V) / omega = 0.2 mm.
  EXPECT_NEAR(held.x, 0.01 * 0.5, 2e-4);
  EXPECT_GT(held.largest_force, 0);
}

TEST(DriveString, ANegativeLateralStiffnessIsRefused) {
  TempDir dir;
  spit(dir / "s.yaml", strip(4, ", lateral_stiffness: -1"));
  const auto r = run_finseg(dir, "run s.yaml --out out --quiet");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("drives[0].lateral_stiffness"), std::string::npos) << r.err;
}

// A toe band is a string's: negative, or on a two-way gauge, it is refused by name.
TEST(DriveString, AToeForceOnlyForAPullOnlyStringAndNotNegative) {
  TempDir dir;
  for (const char* keys : {", toe_force: 0.1", ", pull_only: true, toe_force: -0.1"}) {
    spit(dir / "s.yaml", strip(4, keys));
    const auto r = run_finseg(dir, "run s.yaml --out out --quiet");
    EXPECT_NE(r.code, 0) << keys;
    EXPECT_NE(r.err.find("drives[0].toe_force"), std::string::npos) << r.err;
  }
}

}  // namespace drive_string_test
}  // namespace finseg
