// Per-pair contact forces on request (contact probe `pairs: true`): `<probe>_pairs.csv`
// of a plate resting on a clamped plate under its weight and a load, against m g + P; the
// file written by `finseg run` from a scene file, also when the run diverges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.hpp"
#include "collision/contact_forces.hpp"
#include "collision/contact_laws.hpp"
#include "contact_test_util.hpp"
#include "core/text.hpp"
#include "probes/recorder.hpp"
#include "writers/run_outputs.hpp"

namespace finseg {
namespace contact_pairs_output_test {

using test::run_finseg;
using test::slurp;
using test::spit;
using test::TempDir;

constexpr double kG = 9.81;
constexpr double kThick = 2e-4;  // plate thickness, m
const char* kPairsHeader =
    "body_a,body_b,points,normal_force_N,friction_force_N,max_penetration_m,fx_b_N,fy_b_N,"
    "fz_b_N";

/// Header and cells of every data row of a CSV file.
std::vector<std::vector<std::string>> csv_cells(const std::string& text, std::string* header) {
  std::stringstream in(text);
  std::getline(in, *header);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) rows.push_back(split_csv_line(line));
  return rows;
}

// A clamped 0.1 m square "ground" and a free 0.02 m square "plate" of mass m lying on it,
// pressed by gravity and a load P; anchor friction holds it in the plane (the static solver
// needs a restrained structure). The probe `touch` records the pairs.
Scene plates_scene(double m, double P) {
  Scene scene;
  scene.file = "plates.yaml";
  scene.solver.kind = SolverKind::Static;
  Model& mod = scene.model;
  mod.sheet.length = 0.1;
  mod.sheet.thickness = kThick;
  mod.gravity_W = Vec3(0, 0, -kG);
  const ContactSuggestion sug = suggest_contact(m, kG, 1e-5);
  const double sunk = 0.1 * sug.damping_depth;  // starts touching: its anchors exist
  mod.bodies.push_back(
      test::plate("ground", m, Vec3(0.1, 0.1, kThick), Vec3::Zero(), Mat3::Identity(), true));
  mod.bodies.push_back(
      test::plate("plate", m, Vec3(0.02, 0.02, kThick), Vec3(0, 0, kThick - sunk)));
  LoadDef load;
  load.body = 1;
  load.force = Vec3(0, 0, -P);
  mod.loads.push_back(load);
  mod.contact = test::anchor_contact(sug, 0.5, 0.4);
  ProbeDef probe;
  probe.name = "touch";
  probe.kind = ProbeKind::Contact;
  probe.pairs = true;
  mod.probes.push_back(probe);
  mod.finalize_dofs();
  return scene;
}

TEST(ContactPairsOutput, PlateOnGroundCarriesItsWeightAndLoad) {
  const double m = 1e-3, P = 0.02;
  const Scene scene = plates_scene(m, P);
  State state = initial_state(scene.model);
  commit_contact_history(scene.model, state);  // friction anchors of the touching start
  RunRecorder rec(scene.model, scene.solver, {});
  const SolverStats stats =
      run_solver(scene.model, state, scene.solver,
                 [&](const State& s, const BodyForces& f) { rec.record(s, f); });
  ASSERT_EQ(stats.status, "ok") << stats.message;
  TempDir dir;
  const RunReport report = write_run_outputs(dir / "out", scene, rec, stats, 0.0);
  EXPECT_NE(std::find(report.files.begin(), report.files.end(), "touch_pairs.csv"),
            report.files.end());

  std::string header;
  const auto rows = csv_cells(slurp(dir / "out/touch_pairs.csv"), &header);
  EXPECT_EQ(header, std::string("load_scale,") + kPairsHeader);
  ASSERT_EQ(rows.size(), rec.outputs());  // one touching pair at every output
  for (const auto& r : rows) {
    ASSERT_EQ(r.size(), 10u);
    EXPECT_EQ(r[1], "ground");
    EXPECT_EQ(r[2], "plate");
    EXPECT_GT(std::stod(r[3]), 0);
  }
  // The probe's own table counts the same touching pair at every output.
  const auto totals = csv_cells(slurp(dir / "out/touch.csv"), &header);
  ASSERT_EQ(header.substr(header.rfind(',') + 1), "touching_pairs");
  ASSERT_EQ(totals.size(), rows.size());
  for (const auto& r : totals) EXPECT_EQ(r.back(), "1");
  const auto& last = rows.back();
  ASSERT_EQ(std::stod(last[0]), 1.0);  // full load
  const double weight_and_load = m * kG + P;
  EXPECT_NEAR(std::stod(last[4]) / weight_and_load, 1.0, 1e-6);     // normal_force_N
  EXPECT_NEAR(std::stod(last[9]) / weight_and_load, 1.0, 1e-6);     // fz_b_N: pushes plate up
  EXPECT_LT(std::abs(std::stod(last[5])), 1e-6 * weight_and_load);  // no friction needed
  EXPECT_LT(std::abs(std::stod(last[7])), 1e-6 * weight_and_load);
  EXPECT_LT(std::abs(std::stod(last[8])), 1e-6 * weight_and_load);
  EXPECT_GT(std::stod(last[6]), 0);  // penetrated
  EXPECT_LT(std::stod(last[6]), 0.5 * kThick);

  const auto summary = probe_summary(rec.tables()[0]);
  EXPECT_EQ(summary["pairs_file"], "touch_pairs.csv");
  EXPECT_EQ(summary["pair_rows"].get<std::size_t>(), rows.size());
}

const char* kStrip = R"(material: {youngs_modulus: 4e9, density: 800}
sheet: {length: 0.1, width: 0.02, thickness: 1e-4}
discretisation: {segments: 4}
fixtures: {clamp_start: true}
loads:
  - {at: {s: 0.1, y: 0.01}, force: [0, 0, -1e-6]}
contact: {stiffness: 1e6}
probes:
  - {name: touch, type: contact, pairs: true}
  - {name: plain, type: contact}
)";

// A straight strip never touches itself: the file holds the header only.
TEST(ContactPairsOutput, FinsegRunWritesThePairsFileOfASceneFile) {
  TempDir dir;
  spit(dir / "strip.yaml", kStrip);
  const auto r = run_finseg(dir, "run strip.yaml --out out --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(slurp(dir / "out/touch_pairs.csv"), std::string("load_scale,") + kPairsHeader + "\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "out/plain_pairs.csv"));
  const auto j = nlohmann::json::parse(slurp(dir / "out/summary.json"));
  EXPECT_EQ(j["probes"]["touch"]["pairs_file"], "touch_pairs.csv");
  EXPECT_FALSE(j["probes"]["plain"].contains("pairs_file"));
  const std::vector<std::string> files = j["files"];
  EXPECT_NE(std::find(files.begin(), files.end(), "touch_pairs.csv"), files.end());
}

// Far too large an explicit step: exit 3, and the pairs file is kept like the probe CSVs.
TEST(ContactPairsOutput, DivergedRunKeepsThePairsFile) {
  TempDir dir;
  spit(dir / "strip.yaml",
       std::string(kStrip) + "solver: {type: explicit, t_end: 0.1, dt: 0.01}\n");
  const auto r = run_finseg(dir, "run strip.yaml --out out --quiet");
  EXPECT_EQ(r.code, 3) << r.err;
  std::string header;
  const auto rows = csv_cells(slurp(dir / "out/touch_pairs.csv"), &header);
  EXPECT_EQ(header, std::string("t_s,") + kPairsHeader);
  for (const auto& row : rows) EXPECT_EQ(row.size(), 10u);
  EXPECT_FALSE(std::filesystem::exists(dir / "out/touch_pairs.csv.partial"));
}

}  // namespace contact_pairs_output_test
}  // namespace finseg
