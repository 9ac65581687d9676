// The gas in state files (docs/state-file.md, docs/gas.md): a box inflated by an inflator
// through a vent, stopped half way, its gas written as JSON and read back exactly, and the
// inflation continued from it ending where the uninterrupted one does. A state whose gas is
// missing or impossible is refused naming the field.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "elements/chamber_gas.hpp"
#include "pressure_test_util.hpp"
#include "scene/state_file.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace gas_resume_test {

Model inflating_box() {
  Model m;
  ChamberDef c;
  c.name = "box";
  c.gas = GasModel::Adiabatic;
  c.faces = test::add_box(m, 0.1, 0.1, 0.1, false, 0.02);
  test::join_box_edges(m, c.faces, 2e4, 2.0);
  c.inflow = {{0, 1}, {2e-4, 2e-4}, {300, 300}};
  c.vents = {{2e-5, 0.8, 0}};
  test::add_chamber_and_finish(m, c, 0.1);
  return m;
}

State run_to(const Model& m, State s, double t_end, SolverKind kind = SolverKind::Explicit,
             ImplicitScheme scheme = ImplicitScheme::BackwardEuler) {
  SolverSettings set;
  set.kind = kind;
  set.scheme = scheme;
  set.t_end = t_end;
  set.output_interval = 0.005;
  // The state as the last output (a checkpoint) sees it: with the solver's memory.
  State at_output;
  const SolverStats st =
      run_solver(m, s, set, [&](const State& x, const BodyForces&) { at_output = x; });
  EXPECT_EQ(st.status, "ok") << st.message;
  return at_output;
}

// The gas record of an inflation half way (vent at work) goes through the JSON text and
// comes back bit for bit.
TEST(GasResume, GasStateRoundTripsThroughAStateFile) {
  const Model m = inflating_box();
  const State half = run_to(m, initial_state(m), 0.02);
  ASSERT_GT(half.chambers[0].vented, 0);
  ASSERT_GT(half.chambers[0].work, 0);
  const nlohmann::json j = state_json(m, {half, "h"});
  const State back = parse_state_json(nlohmann::json::parse(j.dump()), m, "half.json").state;
  ASSERT_EQ(back.chambers.size(), 1u);
  const ChamberGas &a = half.chambers[0], &b = back.chambers[0];
  for (auto [x, y] : {std::pair{a.mass, b.mass},
                      {a.energy, b.energy},
                      {a.pressure, b.pressure},
                      {a.work, b.work},
                      {a.injected, b.injected},
                      {a.vented, b.vented},
                      {a.temperature, b.temperature},
                      {a.volume, b.volume},
                      {a.t, b.t}}) {
    EXPECT_EQ(x, y);
  }
}

// An inflation stopped half way, written to a state file, read back and continued ends where
// the uninterrupted inflation does: the same poses, velocities and gas in each time-stepping
// solver (the explicit step travels in the state: recomputed from the resumed state, where
// the gas has stiffened the box, it was another step, and the run ended elsewhere).
TEST(GasResume, ResumedInflationEqualsUninterruptedInflation) {
  const Model m = inflating_box();
  for (const auto& [kind, scheme] : {std::pair{SolverKind::Explicit, ImplicitScheme::BackwardEuler},
                                     {SolverKind::Implicit, ImplicitScheme::BackwardEuler},
                                     {SolverKind::Implicit, ImplicitScheme::GeneralizedAlpha}}) {
    const State whole = run_to(m, initial_state(m), 0.03, kind, scheme);
    const State half = run_to(m, initial_state(m), 0.015, kind, scheme);
    ASSERT_GT(half.chambers[0].vented, 0);
    const nlohmann::json j = state_json(m, {half, "h"});
    const State back = parse_state_json(nlohmann::json::parse(j.dump()), m, "half.json").state;
    const State rest = run_to(m, back, 0.03, kind, scheme);
    const std::string run =
        fmt::format("solver {} scheme {}", static_cast<int>(kind), static_cast<int>(scheme));
    EXPECT_EQ(rest.t, whole.t) << run;
    // To round-off, as the command line's resumed runs (CliRunSafety.Resumed*): m, m/s, rad/s.
    const auto near = [&](const auto& a, const auto& b, const std::string& what) {
      EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-12) << run << " " << what;
    };
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      near(rest.p_W[b], whole.p_W[b], fmt::format("p_W of body {}", b));
      near(rest.R_WB[b], whole.R_WB[b], fmt::format("R_WB of body {}", b));
      near(rest.v_W[b], whole.v_W[b], fmt::format("v_W of body {}", b));
      near(rest.w_W[b], whole.w_W[b], fmt::format("w_W of body {}", b));
    }
    const ChamberGas &a = whole.chambers[0], &c = rest.chambers[0];
    for (auto [x, y] : {std::pair{a.mass, c.mass},
                        {a.energy, c.energy},
                        {a.pressure, c.pressure},
                        {a.work, c.work},
                        {a.vented, c.vented}}) {
      EXPECT_NEAR(x / y, 1, 1e-12) << run;
    }
  }
}

TEST(GasResume, MissingOrImpossibleGasIsRefused) {
  const Model m = inflating_box();
  const nlohmann::json good = state_json(m, {initial_state(m), ""});
  const auto refused = [&](nlohmann::json j, const std::string& field) {
    try {
      parse_state_json(j, m, "s.json");
      ADD_FAILURE() << "accepted; expected " << field;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  };
  nlohmann::json j = good;
  j.erase("chambers");
  refused(j, "chambers");
  j = good;
  j["chambers"][0]["mass_kg"] = -1;
  refused(j, "chambers[0].mass_kg");
  j = good;
  j["chambers"][0].erase("vented_kg");
  refused(j, "chambers[0].vented_kg");
  j = good;
  j["chambers"][0]["volume_m3"] = 0;
  refused(j, "chambers[0].volume_m3");
  j = good;
  j["model"]["chambers"] = 2;
  refused(j, "model.chambers");
}

}  // namespace gas_resume_test
}  // namespace finseg
