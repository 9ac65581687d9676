// Gas in chambers (docs/gas.md) against closed forms: isentropic vent flow, exact inflow
// integrals, a rigid chamber filled at constant mass flow (isothermal and adiabatic), the
// blow-down of a rigid chamber through a choked orifice (isothermal exponential, adiabatic
// power law, first-order convergence in the step), p A on the faces, the energy balance of
// an inflating box, the static solver's gas mass as load parameter, and bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "elements/chamber_gas.hpp"
#include "elements/gas_flow.hpp"
#include "pressure_test_util.hpp"
#include "solvers/dofs.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace gas_test {

using test::add_box;
using test::add_chamber_and_finish;
using test::add_plate;
using test::join_box_edges;

constexpr double kR = 287.05, kGamma = 1.4;
constexpr double kA = 0.3, kB = 0.2, kC = 0.5;  // rigid box, m
constexpr double kVolume = kA * kB * kC;

// Six fixed plates of a box and one loose free plate far away (the solvers need a DOF).
Model rigid_box(const ChamberDef& gas) {
  Model m;
  ChamberDef c = gas;
  c.name = "box";
  c.faces = add_box(m, kA, kB, kC, true);
  add_plate(m, "loose", Vec3(0.1, 0.1, 1e-3), Vec3(5, 5, 5));
  add_chamber_and_finish(m, c, 0.5);
  return m;
}

ChamberDef ideal_gas(GasModel model, double p0) {
  ChamberDef c;
  c.gas = model;
  c.gas_constant = kR;
  c.gamma = kGamma;
  c.temperature = 293.15;
  c.initial_pressure = p0;
  return c;
}

// Runs `kind` to t_end and returns the chamber's gas at every output.
std::vector<ChamberGas> run_gas(const Model& m, SolverKind kind, double t_end, double dt) {
  State st = initial_state(m);
  SolverSettings set;
  set.kind = kind;
  set.t_end = t_end;
  set.dt = dt;
  set.output_interval = t_end / 10;
  std::vector<ChamberGas> out;
  const SolverStats stats = run_solver(
      m, st, set, [&](const State& s, const BodyForces&) { out.push_back(s.chambers[0]); });
  EXPECT_EQ(stats.status, "ok") << stats.message;
  return out;
}

// Mass flux through a nozzle from the Mach number at its throat (textbook isentropic
// relations), an independent route to the vent formula.
double nozzle_flux(double p0, double T0, double pa) {
  const double g = kGamma;
  double pr = pa / p0;
  const double critical = std::pow(2 / (g + 1), g / (g - 1));
  pr = std::max(pr, critical);
  const double M = std::sqrt(2 / (g - 1) * (std::pow(pr, -(g - 1) / g) - 1));
  return p0 * std::sqrt(g / (kR * T0)) * M *
         std::pow(1 + (g - 1) / 2 * M * M, -(g + 1) / (2 * (g - 1)));
}

TEST(GasFlow, VentFlowMatchesIsentropicNozzleRelations) {
  VentDef v;
  v.area = 2e-4;
  v.discharge_coefficient = 0.7;
  const double p0 = 3e5, T0 = 320;
  // Gas tables for gamma = 1.4: critical pressure ratio 0.5283, choked flux factor 0.6847.
  EXPECT_NEAR(vent_mass_flow(v, p0, T0, kR, kGamma) / (0.7 * 2e-4 * p0 / std::sqrt(kR * T0)),
              0.6847, 1e-4);
  for (const double ratio : {0.0, 0.3, 0.5283, 0.6, 0.8, 0.95, 0.999}) {
    v.ambient_pressure = ratio * p0;
    EXPECT_NEAR(vent_mass_flow(v, p0, T0, kR, kGamma), 0.7 * 2e-4 * nozzle_flux(p0, T0, ratio * p0),
                1e-12)
        << ratio;
  }
  v.ambient_pressure = 1.01 * p0;
  EXPECT_EQ(vent_mass_flow(v, p0, T0, kR, kGamma), 0.0);  // no back flow
}

TEST(GasFlow, InflowIntegralIsExactForLinearTables) {
  InflowDef in;
  in.at = {0, 1, 3};
  in.mass_flow = {1, 3, 1};          // 1 + 2t, then 3 - (t - 1)
  in.temperature = {300, 400, 200};  // 300 + 100t, then 400 - 100 (t - 1)
  const double cp = 1000;
  // Over [0.5, 2]: mass = int 1 + 2t on [0.5, 1] + int 3 - (t - 1) on [1, 2].
  const InflowIntegral r = integrate_inflow(in, 0.5, 2.0, cp);
  EXPECT_NEAR(r.mass, (0.5 + (1 - 0.25)) + (3 - 0.5), 1e-14);
  // Enthalpy: cp int (1 + 2t)(300 + 100t) on [0.5, 1] + cp int (3 - u)(400 - 100u), u in [0, 1].
  const auto first = [](double t) {
    return 300 * t + (100 + 600) * t * t / 2 + 200 * t * t * t / 3;
  };
  const double second = 1200 - (300 + 400) / 2.0 + 100 / 3.0;
  EXPECT_NEAR(r.enthalpy, cp * (first(1) - first(0.5) + second), 1e-9);
  EXPECT_NEAR(total_inflow_mass(in), 2 + 4, 1e-14);
  EXPECT_EQ(integrate_inflow(in, 3, 5, cp).mass, 0.0);  // no flow after the table
}

TEST(Gas, RigidChamberFillsAtConstantMassFlow) {
  const double mdot = 2e-3, T_in = 350, p0 = 1e5;
  for (const GasModel model : {GasModel::Isothermal, GasModel::Adiabatic}) {
    ChamberDef c = ideal_gas(model, p0);
    c.inflow = {{0, 10}, {mdot, mdot}, {T_in, T_in}};
    const Model m = rigid_box(c);
    for (const SolverKind kind : {SolverKind::Explicit, SolverKind::Implicit}) {
      const auto gas = run_gas(m, kind, 0.5, 1e-3);
      ASSERT_EQ(gas.size(), 11u);
      for (const ChamberGas& g : gas) {
        // Isothermal: p = (m0 + mdot t) R T / V. Adiabatic: U = U0 + mdot cp T_in t,
        // p = (gamma - 1) U / V = p0 + gamma R T_in mdot t / V.
        const double p = model == GasModel::Isothermal
                             ? p0 + mdot * g.t * kR * c.temperature / kVolume
                             : p0 + kGamma * kR * T_in * mdot * g.t / kVolume;
        EXPECT_NEAR(g.pressure / p, 1.0, 1e-12) << g.t;
        EXPECT_NEAR(g.volume / kVolume, 1.0, 1e-14);
        EXPECT_NEAR(g.injected, mdot * g.t, 1e-15);
      }
      EXPECT_NEAR(gas.back().t, 0.5, 1e-12);
    }
  }
}

// Choked blow-down into vacuum. C0 = Cd A k sqrt(gamma R T0) / V with the choked flux factor
// k = (2 / (gamma + 1))^((gamma + 1) / (2 (gamma - 1))). Isothermal: m = m0 exp(-C0 t).
// Adiabatic (the gas left behind expands isentropically), tau = 1 + (gamma - 1) / 2 C0 t:
// p / p0 = tau^(-2 gamma / (gamma - 1)).
//
// The vent flow is advanced by forward Euler (mass and enthalpy out at the last accepted
// state), so the global error is h E(t) + O(h^2) with E' = J E - y'' / 2, E(0) = 0 (the
// local error of Euler is -h^2 y'' / 2). Relative to the exact pressure:
//   isothermal: E / p = -C0^2 t / 2 (scalar y' = -C0 y);
//   adiabatic, state (m, U), both relative errors e_m, e_U: the difference d = e_m - e_U
//   solves d(tau d)/dtau = C0 (3 gamma + 1) / (2 tau), so d = C0 (3 gamma + 1) ln(tau) /
//   (2 tau), and then e_U = gamma C0 / (2 (gamma - 1)) (2 (1 - 1/tau) - (3 gamma + 1)
//   ln(tau) / tau).
TEST(Gas, RigidChamberBlowsDownThroughAChokedVent) {
  const double p0 = 2e5, t_end = 1.0;
  for (const GasModel model : {GasModel::Isothermal, GasModel::Adiabatic}) {
    ChamberDef c = ideal_gas(model, p0);
    c.vents.push_back({5e-4, 0.8, 0});
    const Model m = rigid_box(c);
    const double g = kGamma;
    const double k = std::pow(2 / (g + 1), (g + 1) / (2 * (g - 1)));
    const double C0 = 0.8 * 5e-4 * k * std::sqrt(g * kR * c.temperature) / kVolume;
    const double x = C0 * t_end, tau = 1 + (g - 1) / 2 * x;
    const bool isothermal = model == GasModel::Isothermal;
    const double exact = isothermal ? p0 * std::exp(-x) : p0 * std::pow(tau, -2 * g / (g - 1));
    const double E = isothermal ? -C0 * x / 2
                                : g * C0 / (2 * (g - 1)) *
                                      (2 * (1 - 1 / tau) - (3 * g + 1) * std::log(tau) / tau);
    ASSERT_GT(x, 1.0);  // a real blow-down, not a small change
    double error[2];
    for (int r = 0; r < 2; ++r) {
      const double h = 1e-3 / (1 << r);
      const auto gas = run_gas(m, SolverKind::Explicit, t_end, h);
      error[r] = gas.back().pressure / exact - 1;
      // The leading term; the next one is O(C0 h) = 0.3 % of it.
      EXPECT_NEAR(error[r] / (h * E), 1.0, 0.01) << h;
    }
    EXPECT_NEAR(error[0] / error[1], 2.0, 0.02);  // first order in the step
  }
}

// A prescribed pressure on a rigid box: each fixed face carries p A along its outward normal.
TEST(Gas, PrescribedPressurePushesEachFaceWithPA) {
  ChamberDef c;
  c.gas = GasModel::Prescribed;
  c.prescribed.pressure = 1234;
  const Model m = rigid_box(c);
  const State st = initial_state(m);
  BodyForces f;
  compute_forces(m, st, f);
  for (const ChamberFace& face : m.chambers[0].faces) {
    const Vec3 n = (face.outward_plus_z ? 1.0 : -1.0) * st.R_WB[face.body].col(2);
    EXPECT_LT((f.f_W[face.body] - 1234 * segment_area(m.bodies[face.body]) * n).norm(), 1e-12);
  }
}

// A free box of six plates joined at its edges, filled from vacuum by an inflator, explicit
// and undamped: the gas work equals the structure's elastic plus kinetic energy, and the
// adiabatic gas's internal energy plus both equals the injected enthalpy.
TEST(Gas, InflationOfAFloatingBoxConservesEnergy) {
  Model m;
  ChamberDef c = ideal_gas(GasModel::Adiabatic, 0);
  c.name = "box";
  c.faces = add_box(m, 0.1, 0.1, 0.1, false, 0.02);
  join_box_edges(m, c.faces, 2e4, 2.0);
  ASSERT_EQ(m.elements.size(), 24u);
  // p = (gamma - 1) U / V = gamma R T_in mdot t / V: about 1.2 kPa after 0.05 s in 1 litre
  // (the former 2e-6 kg/s gave 100 times less, 12 Pa, which is what the code computed).
  const double mdot = 2e-4, T_in = 300;
  c.inflow = {{0, 1}, {mdot, mdot}, {T_in, T_in}};
  add_chamber_and_finish(m, c, 0.1);
  State st = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Explicit;
  set.t_end = 0.05;
  set.output_interval = 0.005;
  double largest_work = 0;
  const SolverStats stats = run_solver(m, st, set, [&](const State& s, const BodyForces& f) {
    const ChamberGas& g = s.chambers[0];
    const double structure = f.potential_energy + kinetic_energy(m, s);
    largest_work = std::max(largest_work, g.work);
    if (g.work < 1e-3 * largest_work || g.work == 0) return;
    EXPECT_NEAR(structure / g.work, 1.0, 0.01) << s.t;
    const double cp = kGamma * kR / (kGamma - 1);
    EXPECT_NEAR((g.energy + structure) / (g.injected * cp * T_in), 1.0, 0.01) << s.t;
  });
  ASSERT_EQ(stats.status, "ok") << stats.message;
  EXPECT_GT(st.chambers[0].pressure, 1000);
  EXPECT_GT(st.chambers[0].volume, 1e-3 * (1 + 1e-4));  // it did inflate
}

// Static solver: the gas mass is the load parameter. A lid on a fixed box held by stiff
// springs at its edges rises by p A / (8 k) with p = m R T / V (isothermal).
TEST(Gas, StaticSolverLoadsTheGasMass) {
  Model m;
  ChamberDef c = ideal_gas(GasModel::Isothermal, 0);
  c.name = "box";
  c.faces = add_box(m, 0.1, 0.1, 0.1, true);
  m.bodies[c.faces[0].body].fixed = false;  // the lid (top face)
  const double k = 1e6;
  join_box_edges(m, c.faces, k, 10.0);
  const double mass = 1e-5;  // about 840 Pa in 1 litre
  c.inflow = {{0, 1}, {mass, mass}, {300, 300}};
  add_chamber_and_finish(m, c, 0.1);
  State st = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Static;
  set.load_steps = 2;
  const SolverStats stats = run_solver(m, st, set, {});
  ASSERT_EQ(stats.status, "ok") << stats.message;
  const double p = mass * kR * c.temperature / 1e-3;
  EXPECT_NEAR(st.chambers[0].pressure / p, 1.0, 1e-3);  // volume change ~1e-5
  const double rise = st.p_W[c.faces[0].body].z() - 0.1;
  EXPECT_NEAR(rise / (p * 0.01 / (8 * k)), 1.0, 1e-3);
}

TEST(Gas, BadInputIsRefusedWithTheField) {
  const auto refused = [](const ChamberDef& c, const std::string& field) {
    try {
      rigid_box(c);
      ADD_FAILURE() << "accepted: " << field;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  };
  ChamberDef p;
  p.gas = GasModel::Prescribed;
  p.prescribed.pressure = -1;
  refused(p, "chambers[0].pressure");
  p.prescribed.pressure = NAN;
  refused(p, "chambers[0].pressure");
  ChamberDef g = ideal_gas(GasModel::Adiabatic, 1e5);
  g.vents.push_back({1.0, 1, 0});  // the box's faces have 0.62 m^2
  refused(g, "chambers[0].vents[0].area");
  g.vents.clear();
  g.inflow = {{0, 0.2, 0.1}, {1, 1, 1}, {300, 300, 300}};
  refused(g, "chambers[0].inflow.at[2]");
  g.inflow = {};
  g.gamma = 1.0;
  refused(g, "chambers[0].gamma");
  // An open chamber: the box without its top.
  Model m;
  ChamberDef open = ideal_gas(GasModel::Isothermal, 1e5);
  open.faces = add_box(m, kA, kB, kC, true);
  open.faces.erase(open.faces.begin());
  m.chambers.push_back(open);
  m.finalize_dofs();
  try {
    prepare_chambers(m);
    ADD_FAILURE() << "open chamber accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("open"), std::string::npos) << e.what();
  }
}

}  // namespace gas_test
}  // namespace finseg
