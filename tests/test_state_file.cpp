// State files (scene/state_file.hpp): exact round trip, validation naming file and field;
// the solvers' stop request; the UTF-8 check of the output folder's pre-flight.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "cli_test_util.hpp"
#include "core/error.hpp"
#include "scene/state_file.hpp"
#include "solvers/solver.hpp"
#include "solvers/stop_request.hpp"
#include "validation_cantilever.hpp"
#include "writers/output_folder.hpp"

namespace finseg {
namespace state_file_test {

// The validation tests' cantilever with 4 segments and a tip load.
Model strip() {
  CantileverSpec spec = validation::slender_strip(4);
  spec.tip_force = Vec3(0, 0, -1e-3);
  return build_cantilever_model(spec);
}

// A state with every field away from its default (values not representable in few digits).
State busy_state(const Model& m) {
  State s = initial_state(m);
  s.t = 0.1 / 3;
  s.load_scale = std::sqrt(0.5);
  for (std::size_t i = 0; i < s.p_W.size(); ++i) {
    s.p_W[i] += Vec3(1e-3 / 7, -2e-17, std::exp(-30.0 * i));
    s.R_WB[i] = Eigen::AngleAxisd(0.3 + i / 9.0, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    s.v_W[i] = Vec3(std::sin(i), 1.0 / 3, -1e-300);
    s.w_W[i] = Vec3(std::cos(i), -7.0 / 11, 2.0);
  }
  for (std::size_t k = 0; k < s.history.size(); ++k)
    s.history[k] = {0.1 * k + 1e-9, int(k), k % 2 == 1, Vec3(3.5 + k, -0.2, 1e-7 * k)};
  s.history[1].rotation_F = Vec3::Zero();  // a joint turned less than 2 rad: not written
  s.contact.anchors = {
      {3, Vec3(1, 2, 3) / 7, Vec3(-1, 0, 1) / 9, 0.25, -1, true, 2.5e-4},
      {18446744073709551615ull, Vec3::Zero(), Vec3::Ones(), 0, 1, false, -1, 3e-5 / 7}};
  s.contact.p_W = s.p_W;
  s.contact.R_WB = s.R_WB;
  s.solver = {1e-6 / 3,
              s.t + 0.01,
              1.0 / 7,
              123456789012,
              s.t,
              s.v_W,
              s.w_W,
              {1.0 / 3, -2e-300, 7},
              {std::sqrt(2.0), 0, -1.0 / 9},
              1e-5 / 7};
  return s;
}

TEST(StateFile, RoundTripIsExact) {
  const Model m = strip();
  const State s = busy_state(m);
  test::TempDir dir;
  write_state_file(dir / "state.json", m, {s, "0123456789abcdef"});
  const StateSnapshot r = read_state_file(dir / "state.json", m);
  EXPECT_EQ(r.scene_hash, "0123456789abcdef");
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "state.json"));
  EXPECT_TRUE(j["elements"][0].contains("rotation_F_rad"));
  EXPECT_FALSE(j["elements"][1].contains("rotation_F_rad"));
  const State& q = r.state;
  EXPECT_EQ(q.t, s.t);
  EXPECT_EQ(q.load_scale, s.load_scale);
  EXPECT_EQ(q.drive_s, s.drive_s);
  ASSERT_EQ(q.p_W.size(), s.p_W.size());
  for (std::size_t i = 0; i < s.p_W.size(); ++i) {
    EXPECT_EQ(q.p_W[i], s.p_W[i]);
    EXPECT_EQ(q.R_WB[i], s.R_WB[i]);
    EXPECT_EQ(q.v_W[i], s.v_W[i]);
    EXPECT_EQ(q.w_W[i], s.w_W[i]);
    EXPECT_EQ(q.contact.p_W[i], s.contact.p_W[i]);
    EXPECT_EQ(q.contact.R_WB[i], s.contact.R_WB[i]);
    EXPECT_EQ(q.solver.f_W[i], s.solver.f_W[i]);
    EXPECT_EQ(q.solver.tau_W[i], s.solver.tau_W[i]);
  }
  ASSERT_EQ(q.history.size(), s.history.size());
  for (std::size_t k = 0; k < s.history.size(); ++k) {
    EXPECT_EQ(q.history[k].fold_angle, s.history[k].fold_angle);
    EXPECT_EQ(q.history[k].openings, s.history[k].openings);
    EXPECT_EQ(q.history[k].opened, s.history[k].opened);
    EXPECT_EQ(q.history[k].rotation_F, s.history[k].rotation_F);
  }
  ASSERT_EQ(q.contact.anchors.size(), 2u);
  for (std::size_t a = 0; a < 2; ++a) {
    const ContactAnchor &x = q.contact.anchors[a], &y = s.contact.anchors[a];
    EXPECT_EQ(x.key, y.key);
    EXPECT_EQ(x.r_src_B, y.r_src_B);
    EXPECT_EQ(x.r_tgt_B, y.r_tgt_B);
    EXPECT_EQ(x.impact_speed, y.impact_speed);
    EXPECT_EQ(x.side, y.side);
    EXPECT_EQ(x.sliding, y.sliding);
    EXPECT_EQ(x.slip_speed, y.slip_speed);
    EXPECT_EQ(x.overlap, y.overlap);
  }
  EXPECT_EQ(q.solver.t, s.solver.t);
  EXPECT_EQ(q.solver.dt, s.solver.dt);
  EXPECT_EQ(q.solver.next_output, s.solver.next_output);
  EXPECT_EQ(q.solver.t_start, s.solver.t_start);
  EXPECT_EQ(q.solver.steps, s.solver.steps);
  EXPECT_EQ(q.solver.vdot, s.solver.vdot);
  EXPECT_EQ(q.solver.accel, s.solver.accel);
  EXPECT_EQ(q.solver.h_prev, s.solver.h_prev);
}

// The message of the InputError that parsing `j` throws ("" if none).
std::string parse_error(const nlohmann::json& j, const Model& m) {
  try {
    parse_state_json(j, m, "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(StateFile, ValidationNamesFileAndField) {
  const Model m = strip();
  const nlohmann::json good = state_json(m, {busy_state(m), ""});
  EXPECT_EQ(parse_error(good, m), "");
  auto j = good;
  j["format"] = "other";
  EXPECT_NE(parse_error(j, m).find("s.json: format:"), std::string::npos);
  j = good;
  j["model"]["bodies"] = 99;
  EXPECT_NE(parse_error(j, m).find("s.json: model.bodies: the scene's model has"),
            std::string::npos);
  j = good;
  j["bodies"][2]["R_WB"][0] = 2.0;
  EXPECT_NE(parse_error(j, m).find("s.json: bodies[2].R_WB: not a rotation"), std::string::npos);
  j = good;
  j["bodies"][1].erase("v_W_m_s");
  EXPECT_NE(parse_error(j, m).find("s.json: bodies[1].v_W_m_s: missing"), std::string::npos);
  j = good;
  j["elements"][0]["openings"] = -1;
  EXPECT_NE(parse_error(j, m).find("s.json: elements[0].openings: expected 0..1000000"),
            std::string::npos);
  j = good;
  j["contact"]["anchors"][1]["key"] = 1u;
  EXPECT_NE(parse_error(j, m).find("s.json: contact.anchors[1].key: keys must ascend"),
            std::string::npos);
  j = good;
  j["contact"]["anchors"][0]["slip_speed_m_s"] = -0.5;
  EXPECT_NE(parse_error(j, m).find("s.json: contact.anchors[0].slip_speed_m_s: expected -1"),
            std::string::npos);
  j = good;  // written before the key existed: read as not known
  j["contact"]["anchors"][0].erase("slip_speed_m_s");
  EXPECT_EQ(parse_error(j, m), "");
  j = good;
  j["contact"]["anchors"][1]["overlap_m"] = -1e-6;
  EXPECT_NE(parse_error(j, m).find("s.json: contact.anchors[1].overlap_m: expected a penetration"),
            std::string::npos);
  j = good;  // written before the key existed: no overlap
  j["contact"]["anchors"][1].erase("overlap_m");
  EXPECT_EQ(parse_error(j, m), "");
  j = good;
  j["t"] = "soon";
  EXPECT_NE(parse_error(j, m).find("s.json: t: expected a finite number"), std::string::npos);
}

// A stop request ends the run at the next output with the State at that output.
TEST(StopRequest, EndsTheRunAtTheNextOutput) {
  const Model m = strip();
  for (SolverKind kind : {SolverKind::Explicit, SolverKind::Implicit}) {
    State s = initial_state(m);
    SolverSettings set;
    set.kind = kind;
    set.t_end = 0.01;
    int outputs = 0;
    double last_t = -1;
    clear_stop_request();
    const SolverStats stats = run_solver(m, s, set, [&](const State& x, const BodyForces&) {
      last_t = x.t;
      if (++outputs == 5) request_stop();
    });
    clear_stop_request();
    EXPECT_EQ(stats.status, "interrupted");
    EXPECT_EQ(outputs, 5);
    EXPECT_EQ(s.t, last_t);
    // The 5th output: the first step at or past 4 output intervals.
    EXPECT_GE(s.t, 4 * 0.01 / 100 - 1e-12);
    EXPECT_LE(s.t, 4 * 0.01 / 100 + stats.largest_step);
  }
}

// Between outputs a stop request ends the run at the next accepted step, with the solver's
// memory in the State; continued from it, the run ends where an uninterrupted one does
// (explicit: to the bit, the same steps; implicit: within the steps' error tolerance, its kept
// Newton matrix is not saved).
TEST(StopRequest, EndsTheRunBetweenOutputsAtTheNextStep) {
  const Model m = strip();
  for (SolverKind kind : {SolverKind::Explicit, SolverKind::Implicit}) {
    SolverSettings set;
    set.kind = kind;
    set.t_end = 0.01;
    set.output_interval = set.t_end;  // outputs at the start and the end only
    State whole = initial_state(m);
    ASSERT_EQ(run_solver(m, whole, set, nullptr).status, "ok");
    State s = initial_state(m);
    std::vector<State> outputs;
    clear_stop_request();
    const SolverStats stats = run_solver(
        m, s, set, [&](const State& x, const BodyForces&) { outputs.push_back(x); },
        [](const SolverProgress& p) {
          if (p.stats->steps == 3) request_stop();
        });
    clear_stop_request();
    EXPECT_EQ(stats.status, "interrupted");
    EXPECT_EQ(stats.steps, 4);
    ASSERT_EQ(outputs.size(), 1u);  // the start: the stop is no output
    EXPECT_EQ(s.solver.t, s.t);
    EXPECT_LT(s.t, 0.5 * set.t_end);
    State resumed = s;  // what the checkpoint holds
    ASSERT_EQ(run_solver(m, resumed, set, nullptr).status, "ok");
    EXPECT_EQ(resumed.t, whole.t);
    // Implicit: the steps' local error tolerance (the runs part where the Newton iterates do).
    const double tol = kind == SolverKind::Explicit ? 0.0 : set.atol + set.rtol * m.sheet.length;
    for (size_t b = 0; b < m.bodies.size(); ++b) {
      EXPECT_LE((resumed.p_W[b] - whole.p_W[b]).norm(), tol) << b;
    }
  }
}

TEST(OutputFolder, Utf8CheckFollowsTheStandard) {
  for (const char* ok : {"", "plain", "\xc3\xa9t\xc3\xa9", "\xe2\x82\xac", "\xf0\x9f\x98\x80",
                         "\xed\x9f\xbf", "\xf4\x8f\xbf\xbf"}) {
    EXPECT_TRUE(is_valid_utf8(ok)) << ok;
  }
  for (const char* bad : {"\xff", "\xc0\xaf", "\xc3", "\xe0\x80\xaf", "\xed\xa0\x80",
                          "\xf0\x8f\xbf\xbf", "\xf4\x90\x80\x80", "a\x80", "\xe2\x82"}) {
    EXPECT_FALSE(is_valid_utf8(bad)) << bad;
  }
}

}  // namespace state_file_test
}  // namespace finseg
