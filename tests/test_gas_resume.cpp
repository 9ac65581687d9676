// The gas in state files (docs/state-file.md, docs/gas.md): a box inflated by an inflator
// through a vent, stopped half way, its gas written as JSON and read back exactly. A state
// whose gas is missing or impossible is refused naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "elements/chamber_gas.hpp"
#include "pressure_test_util.hpp"
#include "scene/state_file.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace {

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

State run_to(const Model& m, State s, double t_end) {
  SolverSettings set;
  set.kind = SolverKind::Explicit;
  set.t_end = t_end;
  set.output_interval = 0.005;
  const SolverStats st = run_solver(m, s, set, nullptr);
  EXPECT_EQ(st.status, "ok") << st.message;
  return s;
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

}  // namespace
}  // namespace finseg
