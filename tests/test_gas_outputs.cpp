// Chamber outputs of a run (docs/scene.md, "Run outputs"): the chamber CSV, its plot, the
// final and peak values in summary.json, the pressure chart in the HTML page and the gas
// work in the energy probe, read back from the files and checked against the physics (the
// adiabatic filling law, the work p dV against the structure's energy).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_test_util.hpp"
#include "elements/chamber_gas.hpp"
#include "pressure_test_util.hpp"
#include "probes/recorder.hpp"
#include "solvers/dofs.hpp"
#include "writers/run_outputs.hpp"

namespace finseg {
namespace gas_outputs_test {

using test::TempDir;

constexpr double kR = 287.05, kGamma = 1.4, kMdot = 2e-4, kTin = 300;

// A fixed 0.1 m box whose lid is free, held by stiff bushings at its edges, filled from
// vacuum by an adiabatic inflator (about 1.2 kPa after 0.05 s); an energy probe.
Scene inflated_box() {
  Scene scene;
  scene.file = "box.yaml";
  scene.title = "box";
  Model& m = scene.model;
  ChamberDef c;
  c.name = "box";
  c.gas = GasModel::Adiabatic;
  c.gas_constant = kR;
  c.gamma = kGamma;
  c.faces = test::add_box(m, 0.1, 0.1, 0.1, true);
  m.bodies[c.faces[0].body].fixed = false;  // the lid
  test::join_box_edges(m, c.faces, 2e4, 2.0);
  c.inflow = {{0, 1}, {kMdot, kMdot}, {kTin, kTin}};
  ProbeDef energy;
  energy.name = "energy";
  energy.kind = ProbeKind::Energy;
  m.probes.push_back(energy);
  test::add_chamber_and_finish(m, c, 0.1);
  scene.solver.kind = SolverKind::Explicit;
  scene.solver.t_end = 0.05;
  scene.solver.output_interval = 0.005;
  scene.outputs.plot = true;
  scene.outputs.html = true;
  return scene;
}

std::size_t column(const std::string& header, const std::string& name) {
  std::stringstream in(header);
  std::string cell;
  for (std::size_t i = 0; std::getline(in, cell, ','); ++i) {
    if (cell == name) return i;
  }
  ADD_FAILURE() << name << " not in " << header;
  return 0;
}

TEST(GasOutputs, ChamberCsvPlotSummaryHtmlAndEnergyWork) {
  const Scene scene = inflated_box();
  State state = initial_state(scene.model);
  RunRecorder rec(scene.model, scene.solver, {true, false, {}});
  const SolverStats stats =
      run_solver(scene.model, state, scene.solver,
                 [&](const State& s, const BodyForces& f) { rec.record(s, f); });
  ASSERT_EQ(stats.status, "ok") << stats.message;
  TempDir dir;
  const RunReport report = write_run_outputs(dir / "out", scene, rec, stats, 0.0);
  EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();

  std::string header;
  const auto rows = test::csv_rows(test::slurp(dir / "out/chamber_box.csv"), &header);
  EXPECT_EQ(header, "t_s,pressure_Pa,volume_m3,mass_kg,temperature_K,work_J,injected_kg,vented_kg");
  ASSERT_EQ(rows.size(), 11u);
  double largest = 0;
  for (const auto& r : rows) {
    // Adiabatic filling from vacuum: U = H_in - W, p = (gamma - 1) U / V; the lid moves
    // little (the work is a 1e-4 part), so p = gamma R T_in mdot t / V to 1 %.
    const double t = r[0], V = r[2];
    EXPECT_NEAR(r[6], kMdot * t, 1e-15);  // injected
    EXPECT_NEAR(r[3], kMdot * t, 1e-15);  // mass: no vents
    const double cp = kGamma * kR / (kGamma - 1);
    EXPECT_NEAR(r[1] * V / (kGamma - 1), kMdot * t * cp * kTin - r[5], 1e-9 * (1 + r[1]));
    if (t > 0) {
      EXPECT_NEAR(r[1] / (kGamma * kR * kTin * kMdot * t / V), 1.0, 0.01) << t;
    }
    largest = std::max(largest, r[1]);
  }
  EXPECT_GT(rows.back()[2], 1e-3);  // the lid rose

  const auto summary = nlohmann::json::parse(test::slurp(dir / "out/summary.json"));
  const auto& probe = summary["probes"]["chamber_box"];
  EXPECT_EQ(probe["type"], "chamber");
  EXPECT_EQ(probe["file"], "chamber_box.csv");
  // The CSV carries 12 significant digits, summary.json the doubles.
  EXPECT_NEAR(probe["final"]["pressure_Pa"].get<double>() / rows.back()[1], 1.0, 1e-11);
  EXPECT_NEAR(probe["peak"]["pressure_Pa"].get<double>() / largest, 1.0, 1e-11);
  EXPECT_NEAR(probe["peak_pressure_at"].get<double>() / rows.back()[0], 1.0, 1e-11);  // filling

  const std::string png = test::slurp(dir / "out/chamber_box.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");

  const std::string html = test::slurp(dir / "out/animation.html");
  const auto at =
      html.find("\"curves\":[{\"xLabel\":\"time [s]\",\"yLabel\":\"chamber_box pressure [Pa]\"");
  EXPECT_NE(at, std::string::npos);

  // Energy probe: the gas work p dV equals the chamber's work and, undamped, the lid's
  // elastic plus kinetic energy (trapezoidal work against Verlet: 1 %).
  const auto energy = test::csv_rows(test::slurp(dir / "out/energy.csv"), &header);
  const std::size_t w = column(header, "gas_work_J"), total = column(header, "total_J");
  ASSERT_EQ(energy.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_NEAR(energy[i][w], rows[i][5], 1e-11 * std::abs(rows[i][5]));
    if (i > 2) {
      EXPECT_NEAR(energy[i][total] / energy[i][w], 1.0, 0.01) << rows[i][0];
    }
  }
  EXPECT_GT(energy.back()[w], 0);
}

}  // namespace gas_outputs_test
}  // namespace finseg
