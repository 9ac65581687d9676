// Pressure loads (docs/pressure.md): resultant p A n on fixed and rotated plates, the
// follower direction, tables, exact Jacobian, equilibrium and motion under pressure in the
// three solvers against closed forms, and bad scene input.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "elements/assemble.hpp"
#include "elements/pressure.hpp"
#include "jacobian_test_util.hpp"
#include "pressure_test_util.hpp"
#include "scene/scene_reader.hpp"
#include "solvers/dofs.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace pressure_test {

using test::add_plate;

const Vec3 kSize(0.2, 0.1, 1e-3);  // A = 0.02 m^2
constexpr double kArea = 0.02;

PressureDef constant_pressure(int body, double p, PressureSide side) {
  PressureDef d;
  d.bodies = {body};
  d.pressure = p;
  d.side = side;
  return d;
}

BodyForces forces_at(const Model& m, const State& st) {
  BodyForces f;
  compute_forces(m, st, f);
  return f;
}

TEST(Pressure, FixedPlateResultantIsPAN) {
  Model m;
  add_plate(m, "plate", kSize, Vec3(0.3, -0.1, 0.5), Mat3::Identity(), 0.02, true);
  m.pressures.push_back(constant_pressure(0, 250, PressureSide::PlusZ));
  m.finalize_dofs();
  validate(m);
  const BodyForces f = forces_at(m, initial_state(m));
  EXPECT_LT((f.f_W[0] - Vec3(0, 0, -250 * kArea)).norm(), 1e-14);
  EXPECT_LT(f.tau_W[0].norm(), 1e-14);  // resultant through the centroid
  m.pressures[0].side = PressureSide::MinusZ;
  EXPECT_LT((forces_at(m, initial_state(m)).f_W[0] - Vec3(0, 0, 250 * kArea)).norm(), 1e-14);
}

TEST(Pressure, RotatedPlateAndFollowerDirection) {
  const Mat3 R = so3_exp(Vec3(0.4, -0.9, 0.3));
  Model m;
  add_plate(m, "plate", kSize, Vec3(0.1, 0.2, 0.3), R);
  m.pressures.push_back(constant_pressure(0, 80, PressureSide::MinusZ));
  m.finalize_dofs();
  State st = initial_state(m);
  BodyForces f = forces_at(m, st);
  const Vec3 n_W = R.col(2);  // MinusZ: the fluid on -z pushes along +z_B
  EXPECT_LT((f.f_W[0] - 80 * kArea * n_W).norm(), 1e-14);
  // Moment about the world origin = r x f: the force acts at the centroid.
  const Vec3 m_O = st.p_W[0].cross(f.f_W[0]) + f.tau_W[0];
  EXPECT_LT((m_O - st.p_W[0].cross(80 * kArea * n_W)).norm(), 1e-14);
  // Turn the plate further: the force turns with it (follower), its size stays p A.
  const Mat3 dR = so3_exp(Vec3(1.1, 0.2, -0.5));
  st.R_WB[0] = dR * st.R_WB[0];
  f = forces_at(m, st);
  EXPECT_LT((f.f_W[0] - 80 * kArea * (dR * n_W)).norm(), 1e-14);
}

TEST(Pressure, TableInterpolatesLinearlyAndHoldsEnds) {
  PressureDef d;
  d.bodies = {0};
  d.at = {1, 2, 4};
  d.pressures = {10, 30, 0};
  EXPECT_DOUBLE_EQ(pressure_now(d, 0.0, 1), 10);    // held before the table
  EXPECT_DOUBLE_EQ(pressure_now(d, 1.5, 1), 20);    // midway 10..30
  EXPECT_DOUBLE_EQ(pressure_now(d, 3.0, 1), 15);    // midway 30..0
  EXPECT_DOUBLE_EQ(pressure_now(d, 9.0, 1), 0);     // held after
  EXPECT_DOUBLE_EQ(pressure_now(d, 1.5, 0.5), 20);  // a time table ignores the load scale
  d.versus = PressureVersus::LoadScale;
  EXPECT_DOUBLE_EQ(pressure_now(d, 99, 1.25), 15);  // 10 + 0.25 * (30 - 10)
  PressureDef c;
  c.pressure = 40;
  EXPECT_DOUBLE_EQ(pressure_now(c, 7, 0.25), 10);  // constant: scaled by the load scale
}

TEST(Pressure, JacobianMatchesFiniteDifferencesAndIsUnsymmetric) {
  Model m;
  add_plate(m, "a", kSize, Vec3(0.1, 0.0, 0.2), so3_exp(Vec3(0.3, 0.7, -0.2)));
  add_plate(m, "b", Vec3(0.05, 0.3, 1e-3), Vec3(-0.2, 0.1, 0), so3_exp(Vec3(-1.2, 0.1, 0.4)));
  m.pressures.push_back(constant_pressure(0, 120, PressureSide::PlusZ));
  m.pressures.push_back(constant_pressure(1, 60, PressureSide::MinusZ));
  m.pressures[1].bodies = {0, 1};
  m.finalize_dofs();
  const State st = initial_state(m);
  BodyForces f;
  ForceJacobian jac;
  compute_forces(m, st, f, &jac);
  const Eigen::MatrixXd J = jac.dq;
  const double h = 1e-6;
  for (int c = 0; c < m.num_dofs; ++c) {
    const Eigen::VectorXd fd = test::fd_pose_column(m, st, c, h);
    EXPECT_LE((fd - J.col(c)).norm(), 1e-6 * J.norm()) << "column " << c;
  }
  // d force / d rotation is p A [n]x-like, d moment / d position is zero: unsymmetric.
  EXPECT_GT((J.block<3, 3>(0, 3).norm()), 1.0);
  EXPECT_EQ((J.block<3, 3>(3, 0).norm()), 0.0);
}

// A plate hung on a bushing under gravity (-z) and a pressure from below (+z): the
// bushing stretches by (p A - m g) / k_z; with p A = m g it stays at rest.
TEST(Pressure, StaticPlateAgainstGravity) {
  const double mass = 0.05, g = 9.81, kz = 200;
  for (const double ratio : {1.0, 3.0}) {
    Model m;
    add_plate(m, "base", kSize, Vec3::Zero(), Mat3::Identity(), mass, true);
    add_plate(m, "plate", kSize, Vec3::Zero(), Mat3::Identity(), mass);
    ElementDef e;
    e.inner = 1;
    e.outer = 0;
    e.K << 500, 500, kz, 5, 5, 5;
    m.elements.push_back(e);
    m.gravity_W = Vec3(0, 0, -g);
    m.pressures.push_back(constant_pressure(1, ratio * mass * g / kArea, PressureSide::MinusZ));
    m.sheet.length = 0.2;
    m.finalize_dofs();
    validate(m);
    State st = initial_state(m);
    SolverSettings set;
    set.kind = SolverKind::Static;
    set.load_steps = 4;
    const SolverStats stats = run_solver(m, st, set, {});
    ASSERT_EQ(stats.status, "ok") << stats.message;
    const double dz = (ratio - 1) * mass * g / kz;
    EXPECT_NEAR(st.p_W[1].z(), dz, 1e-9 * (1 + dz)) << ratio;
    EXPECT_LT(st.p_W[1].head<2>().norm(), 1e-12);
  }
}

// A free plate pushed by a pressure ramp p = r t: z(t) = r A t^3 / (6 m), in the explicit
// and the implicit solver (the table is indexed by time).
TEST(Pressure, FreePlateUnderPressureRampInDynamicSolvers) {
  const double mass = 0.01, rate = 50, t_end = 0.2;
  for (const SolverKind kind : {SolverKind::Explicit, SolverKind::Implicit}) {
    Model m;
    add_plate(m, "plate", kSize, Vec3::Zero(), Mat3::Identity(), mass);
    PressureDef d;
    d.bodies = {0};
    d.side = PressureSide::MinusZ;
    d.at = {0, 1};
    d.pressures = {0, rate};
    m.pressures.push_back(d);
    m.sheet.length = 0.2;
    m.finalize_dofs();
    State st = initial_state(m);
    SolverSettings set;
    set.kind = kind;
    set.t_end = t_end;
    set.dt = 1e-4;
    set.rtol = 1e-8;
    set.atol = 1e-12;
    const SolverStats stats = run_solver(m, st, set, {});
    ASSERT_EQ(stats.status, "ok") << stats.message;
    const double z = rate * kArea * std::pow(t_end, 3) / (6 * mass);
    EXPECT_NEAR(st.p_W[0].z() / z, 1.0, 1e-3) << static_cast<int>(kind);
    EXPECT_LT(st.p_W[0].head<2>().norm(), 1e-12);
  }
}

const char* kScene = R"(material: {youngs_modulus: 4e9, density: 800}
sheet: {length: 0.1, width: 0.02, thickness: 1e-4}
discretisation: {segments: 4}
fixtures: {clamp_start: true}
pressures:
  - {name: blow, bodies: all, side: -z, pressure: 5}
  - {panels: [1], side: +z, table: {versus: time, at: [0, 1], pressure: [0, 2]}}
)";

TEST(PressureScene, ReadsTheSection) {
  const Scene s = parse_scene(kScene, "p.yaml");
  ASSERT_EQ(s.model.pressures.size(), 2u);
  EXPECT_EQ(s.model.pressures[0].name, "blow");
  EXPECT_EQ(s.model.pressures[0].bodies.size(), s.model.bodies.size());
  EXPECT_EQ(s.model.pressures[0].side, PressureSide::MinusZ);
  EXPECT_EQ(s.model.pressures[0].pressure, 5);
  EXPECT_EQ(s.model.pressures[1].side, PressureSide::PlusZ);
  EXPECT_EQ(s.model.pressures[1].bodies.size(), s.model.bodies.size());  // one panel
  EXPECT_EQ(s.model.pressures[1].pressures[1], 2);
}

void expect_refused(const std::string& find, const std::string& replace, const std::string& field,
                    const std::string& words) {
  std::string text = kScene;
  const auto at = text.find(find);
  ASSERT_NE(at, std::string::npos) << find;
  text.replace(at, find.size(), replace);
  try {
    parse_scene(text, "p.yaml");
    ADD_FAILURE() << "accepted " << replace;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "p.yaml") << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(PressureScene, RefusesBadInput) {
  expect_refused("pressure: 5", "pressure: -5", "pressures[0].pressure", ">= 0 Pa");
  expect_refused("pressure: 5", "pressure: .nan", "pressures[0].pressure", ">= 0 Pa");
  expect_refused("pressure: [0, 2]", "pressure: [0, -2]", "pressures[1].table.pressure[1]",
                 ">= 0 Pa");
  expect_refused("at: [0, 1]", "at: [1, 0]", "pressures[1].at[1]", "strictly ascending");
  expect_refused("panels: [1]", "panels: [2]", "pressures[1].panels[0]", "[1, 1]");
  expect_refused("bodies: all", "bodies: [nobody]", "pressures[0].bodies[0]", "not a body");
  expect_refused("side: -z", "side: up", "pressures[0].side", "allowed: +z, -z");
  expect_refused("at: [0, 1]", "at: [0, 1, 2]", "pressures[1].pressure", "one per entry");
  expect_refused(", pressure: 5", "", "pressures[0].pressure", "either pressure");
}

TEST(PressureModel, ValidateRefusesBadDefinitions) {
  Model m;
  add_plate(m, "plate", kSize, Vec3::Zero());
  m.finalize_dofs();
  m.pressures.push_back(constant_pressure(3, 1, PressureSide::PlusZ));
  EXPECT_THROW(validate(m), InputError);  // unknown body index
  m.pressures[0] = constant_pressure(0, -1, PressureSide::PlusZ);
  EXPECT_THROW(validate(m), InputError);
  m.pressures[0] = constant_pressure(0, std::nan(""), PressureSide::PlusZ);
  EXPECT_THROW(validate(m), InputError);
  m.pressures[0] = constant_pressure(0, 1, PressureSide::PlusZ);
  m.pressures[0].at = {0, 0};
  m.pressures[0].pressures = {1, 2};
  EXPECT_THROW(validate(m), InputError);  // repeated abscissa
  m.pressures[0].at = {0, 1};
  EXPECT_NO_THROW(validate(m));
}

}  // namespace pressure_test
}  // namespace finseg
